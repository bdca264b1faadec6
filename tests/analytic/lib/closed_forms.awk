# Closed forms shared by the cases in tests/analytic (mawk-compatible awk functions; each
# case's closed.awk is loaded after this file). All in RADIANCE units: radiance W/(sr m2),
# irradiance W/m2 per channel (the scenes are grey).

function pi_() { return atan2(0, -1) }
function abs_(x) { return x < 0 ? -x : x }

# Irradiance at point P (normal N, unit) from a Lambertian polygon of radiance L that lies
# wholly in front of P's tangent plane (Lambert's contour integral, e.g. Howell's catalogue
# of configuration factors, "differential area to polygon"):
#   E = (L / 2) | sum_i  theta_i  N . (v_i x v_i+1) / |v_i x v_i+1| |,
# v_i = vertex_i - P, theta_i the angle between v_i and v_i+1. E = L pi F(dA -> polygon).
# V holds nv vertices as V[0..3nv-1].
function polyE(L, px, py, pz, nx, ny, nz, nv, V,
               i, j, ax, ay, az, bx, by, bz, cx, cy, cz, lc, th, s) {
    s = 0
    for (i = 0; i < nv; i++) {
        j = (i + 1) % nv
        ax = V[3*i] - px; ay = V[3*i+1] - py; az = V[3*i+2] - pz
        bx = V[3*j] - px; by = V[3*j+1] - py; bz = V[3*j+2] - pz
        cx = ay*bz - az*by; cy = az*bx - ax*bz; cz = ax*by - ay*bx
        lc = sqrt(cx*cx + cy*cy + cz*cz)
        th = atan2(lc, ax*bx + ay*by + az*bz)
        s += th * (nx*cx + ny*cy + nz*cz) / lc
    }
    return L / 2 * abs_(s)
}

# Axis-aligned rectangle as a polygon in V: corners (x0,y0)-(x1,y1) at height z.
function rectZ(V, x0, y0, x1, y1, z) {
    V[0] = x0; V[1] = y0; V[2] = z;  V[3] = x1; V[4] = y0; V[5] = z
    V[6] = x1; V[7] = y1; V[8] = z;  V[9] = x0; V[10] = y1; V[11] = z
    return 4
}

# Irradiance from a uniform Lambertian sphere (radiance L, radius R, centre C) on a
# surface element at P with unit normal N, the sphere wholly above P's tangent plane:
# E = pi L (R/d)^2 cos(theta) exactly (the sphere acts as a point of intensity
# I = pi R^2 L; e.g. Howell's catalogue, "differential area to sphere").
function sphereE(L, R, cx, cy, cz, px, py, pz, nx, ny, nz,    dx, dy, dz, d2, c) {
    dx = cx - px; dy = cy - py; dz = cz - pz
    d2 = dx*dx + dy*dy + dz*dz
    c = (nx*dx + ny*dy + nz*dz) / sqrt(d2)
    return c > 0 ? pi_() * L * R * R * c / d2 : 0
}

# Solid angle of a distant source of full angle `deg` degrees (RADIANCE `source`):
# 2 pi (1 - cos(deg/2)).
function discOmega(deg) { return 2 * pi_() * (1 - cos(deg / 2 * pi_() / 180)) }

# Transmittance of a thin pane of index n with internal transmittance t at normal
# incidence per pass, at incidence cosine ci: Fresnel reflectance r of one face for each
# polarisation, internal transmittance t^(1/cos theta_t) along the slanted path, all the
# inner reflections summed (T = (1-r)^2 tau / (1 - r^2 tau^2)), and the two polarisations
# averaged (unpolarised light). RADIANCE's `glass` is this pane with n = 1.52 (ray.html,
# "Glass").
function paneT(n, t, ci,    ct, rs, rp, tau) {
    ct = sqrt(1 - (1 - ci * ci) / (n * n))
    rs = (ci - n * ct) / (ci + n * ct); rs *= rs
    rp = (ct - n * ci) / (ct + n * ci); rp *= rp
    tau = t ^ (1 / ct)
    return 0.5 * (1 - rs) * (1 - rs) * tau / (1 - rs * rs * tau * tau) + \
           0.5 * (1 - rp) * (1 - rp) * tau / (1 - rp * rp * tau * tau)
}
