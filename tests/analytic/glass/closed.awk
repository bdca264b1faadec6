# E = L omega cos(theta) T(theta) in the patch the pane lights (x in [-3.73, 0.27], y in
# [-2, 2], all points inside), T the thin-pane transmittance (paneT: n = 1.52, internal
# transmittance 0.96 at normal incidence). The caustic photons carry all of it.
BEGIN { ct = cos(pi_() / 6); e = 1e6 * discOmega(.533) * ct * paneT(1.52, .96, ct) }
{ print e, e, 0 }
