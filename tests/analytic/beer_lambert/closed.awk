# E = integral over the panel of L cos(t_s) cos(t_r) / d^2 exp(-sigma l) dA, l = 2 d / h
# the part of the path in the slab (each path crosses its top and bottom); the midpoint
# rule on 40 x 40 cells (10 x 10 agree to 1e-5). Direct photons carry all of it.
{
    n = 40; h = .1 / n; e = 0
    for (i = 0; i < n; i++) for (j = 0; j < n; j++) {
        dx = -.05 + (i + .5) * h - $1; dy = -.05 + (j + .5) * h - $2; dz = 2.5 - $3
        d2 = dx * dx + dy * dy + dz * dz; d = sqrt(d2)
        cr = ($4 * dx + $5 * dy + $6 * dz) / d  # the point's normal is a unit vector
        e += 1000 * (dz / d) * cr / d2 * exp(-.5 * 2 * d / dz) * h * h
    }
    print e, e, 0
}
