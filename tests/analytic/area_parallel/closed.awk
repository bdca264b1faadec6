# E = L pi F(dA -> panel), Lambert's contour integral (polyE); direct photons carry all.
BEGIN { nv = rectZ(V, -.5, -.25, .5, .25, 1.5) }
{ e = polyE(100, $1, $2, $3, $4, $5, $6, nv, V); print e, e, 0 }
