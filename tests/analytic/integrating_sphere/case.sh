# integrating_sphere: classic -ab 12 without cache (-aa 0, -lw 1e-5: repeats independent,
# no weight cut-off bias at this depth); the truncation after 12 bounces leaves out
# rho^12 = 2.4e-4 of the indirect part, and the lamp's shadow on the reflected light at
# most (r / d_min)^2 = (0.01 / 0.5)^2 = 4e-4 of it: stated biases. Photon map: global
# photons read at the point (-ab -1, the direct part computed classically).
CLASSIC="-ab 12 -aa 0 -ad 512 -as 0 -lw 1e-5"
CLASSIC_BIAS=6.4e-4
MAP=-apg; PHOTONS=2m; PHOTONS_LIGHT=200k
K=10000; K_LIGHT=500
RENDER="-ab -1"
PMAP_BIAS=4e-4
LIGHT_POINTS="1 2 3"
