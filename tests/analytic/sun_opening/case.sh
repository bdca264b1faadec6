# sun_opening: direct sunlight only. Classic -ab 0 (-dj 1 jitters over the sun's disc);
# photon map: direct photons emitted from the port in the opening.
CLASSIC="-ab 0 -dj 1"
MAP=-apd; MAP_OPTS="-apo port"; PHOTONS=2m; PHOTONS_LIGHT=200k
K=10000; K_LIGHT=500
RENDER="-ab 0"
LIGHT_POINTS="1 3 6"
