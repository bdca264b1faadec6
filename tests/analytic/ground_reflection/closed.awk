# E = (rho E_sun / pi) pi F(dA -> floor): the floor is a Lambertian rectangle of radiance
# rho L omega / pi (polyE), seen from below the sensor plane facing down. All of it is
# light reflected once: global photons.
BEGIN { nv = rectZ(V, -2, -2, 2, 2, 0); lf = .5 * 1e6 * discOmega(.533) / pi_() }
{ e = polyE(lf, $1, $2, $3, $4, $5, $6, nv, V); print e, e, 0 }
