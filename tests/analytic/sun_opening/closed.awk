# E = L omega cos(theta) in the sunlit patch, the opening moved by 3 tan(30 deg) = 1.732 m
# towards -x: x in [-2.232, -1.232], y in [-1, 1]; 0 elsewhere (direct light only). D: the
# distance from an unlit point to the patch.
BEGIN { pi = pi_(); ct = cos(pi / 6); e0 = 1e6 * discOmega(.533) * ct; sh = 3 * sin(pi / 6) / ct }
{
    x0 = -.5 - sh; x1 = .5 - sh; y0 = -1; y1 = 1
    dx = $1 < x0 ? x0 - $1 : ($1 > x1 ? $1 - x1 : 0)
    dy = $2 < y0 ? y0 - $2 : ($2 > y1 ? $2 - y1 : 0)
    d = sqrt(dx * dx + dy * dy)
    e = d > 0 ? 0 : e0
    print e, e, d
}
