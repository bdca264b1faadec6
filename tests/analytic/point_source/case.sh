# point_source: direct light only. Classic: -ab 0 with jittered source samples (-dj 1);
# photon map: direct photons (-apd), which replace the direct calculation.
CLASSIC="-ab 0 -dj 1"
MAP=-apd; PHOTONS=4m; PHOTONS_LIGHT=300k
K=10000; K_LIGHT=500
RENDER="-ab 0"
LIGHT_POINTS="1 3 5"
