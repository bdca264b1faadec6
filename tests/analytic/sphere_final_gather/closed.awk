# As integrating_sphere: E = E_direct + E_i, E_i = rho Phi / (A (1 - rho)). Through the
# final gather the first bounce (rho Phi / A, the gather hits' direct light) is classic;
# the photons carry the rest, rho E_i (the hits' own indirect irradiance, E_i).
BEGIN { pi = pi_(); rho = .5; ei = pi * .01 * .01 * 1000 * rho / (1 - rho) }
{ ed = sphereE(1000, .01, 0, 0, .5, $1, $2, $3, $4, $5, $6); print ed + ei, rho * ei, 0 }
