# beer_lambert: direct light through an absorber. Classic -ab 0 (the shadow ray takes the
# mist's extinction); photon map: direct photons, absorbed in the slab on their way.
CLASSIC="-ab 0 -dj 1 -ds .01"
MAP=-apd; PHOTONS=1m; PHOTONS_LIGHT=200k
K=5000; K_LIGHT=500
RENDER="-ab 0"
LIGHT_POINTS="1 3 5"
