# E = L pi F(dA -> panel), Lambert's contour integral (polyE); direct photons carry all.
BEGIN {
    split("0 -.5 1  0 .5 1  0 .5 2  0 -.5 2", a, " ")
    for (i = 1; i <= 12; i++) V[i - 1] = a[i]
}
{ e = polyE(100, $1, $2, $3, $4, $5, $6, 4, V); print e, e, 0 }
