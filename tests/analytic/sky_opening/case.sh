# sky_opening: the sky is not a light source for the direct calculation: classic -ab 1
# (-aa 0: no cache, so repeats are independent); photon map: global photons from the
# port (a sky's first hits are global photons in radphoton), read at the point, -ab -1.
# -ds .05: at the default -ds .01 mkpmap first spends 3.6 s (RADIANCE 5.4: 9 s) on the
# sky's angular emission table for each of 2500 port partitions (-dp 1000 per sr), which a
# uniform sky does not need.
CLASSIC="-ab 1 -aa 0 -ad 2048 -as 0"
MAP=-apg; MAP_OPTS="-apo port -ds .05"; PHOTONS=2m; PHOTONS_LIGHT=200k
K=10000; K_LIGHT=500
RENDER="-ab -1"
LIGHT_POINTS="1 3 5"
