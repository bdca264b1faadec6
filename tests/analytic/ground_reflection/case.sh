# ground_reflection: classic -ab 1 (-aa 0: repeats independent; the floor's radiance is
# its direct light); photon map: global photons deposited on the sensor plane, read at the
# point (-ab -1; the point faces away from the sun, no direct part).
CLASSIC="-ab 1 -aa 0 -ad 2048 -as 0"
MAP=-apg; MAP_OPTS="-apo port -aps sensor"; PHOTONS=2m; PHOTONS_LIGHT=200k
K=10000; K_LIGHT=500
RENDER="-ab -1"
LIGHT_POINTS="1 3 5"
