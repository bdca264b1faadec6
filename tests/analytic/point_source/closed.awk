# E = I cos(theta) / d^2 with I = pi R^2 L (sphereE in lib/closed_forms.awk); direct
# photons carry all of it.
{ e = sphereE(1000, .05, 0, 0, 2, $1, $2, $3, $4, $5, $6); print e, e, 0 }
