# area_perpendicular: direct light only, as area_parallel.
CLASSIC="-ab 0 -dj 1 -ds .05"
MAP=-apd; PHOTONS=4m; PHOTONS_LIGHT=300k
K=10000; K_LIGHT=500
RENDER="-ab 0"
LIGHT_POINTS="1 4 6"
