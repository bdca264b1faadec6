# E = E_lamp + rho_m E_image: the lamp (sphereE) and its mirror image 0.5 m below the
# mirror plane, seen through the mirror (every point's reflection point (x, y) / 4 lies on
# it, and the reflected ray passes the lamp >= 0.25 m away). The caustic photons carry
# the image part.
{
    ed = sphereE(1000, .02, 0, 0, .5, $1, $2, $3, $4, $5, $6)
    ei = .8 * sphereE(1000, .02, 0, 0, -.5, $1, $2, $3, $4, $5, $6)
    print ed + ei, ei, 0
}
