# E = E_direct + E_indirect. Direct from the lamp: I cos(theta) / d^2 (sphereE). Indirect:
# uniform over a sphere's inside, E_i = rho Phi / (A (1 - rho)) with Phi = 4 pi^2 r^2 L the
# lamp's flux and A = 4 pi R^2: pi r^2 L rho / (R^2 (1 - rho)). The global photons carry
# the indirect part.
BEGIN { pi = pi_(); rho = .5; ei = pi * .01 * .01 * 1000 * rho / (1 - rho) }
{ ed = sphereE(1000, .01, 0, 0, .5, $1, $2, $3, $4, $5, $6); print ed + ei, ei, 0 }
