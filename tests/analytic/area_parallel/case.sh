# area_parallel: direct light only. Classic -ab 0, jittered source samples (-dj 1,
# -ds 0.05); photon map: direct photons.
CLASSIC="-ab 0 -dj 1 -ds .05"
MAP=-apd; PHOTONS=4m; PHOTONS_LIGHT=300k
K=10000; K_LIGHT=500
RENDER="-ab 0"
LIGHT_POINTS="1 2 4"
