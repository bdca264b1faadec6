# E = L_sky pi F(dA -> opening) (polyE): seen through the opening the sky is a Lambertian
# polygon of radiance L_sky; the sky's first hits are global photons (radphoton).
BEGIN { nv = rectZ(V, -1, -1, 1, 1, 2) }
{ e = polyE(10, $1, $2, $3, $4, $5, $6, nv, V); print e, e, 0 }
