# mirror: classic -ab 0 with the mirror's virtual source (RADIANCE's image method);
# photon map: caustic photons on the sensor plane, -ab 0 (virtual sources off, the
# lamp's direct light classic).
CLASSIC="-ab 0 -dj 1"
MAP=-apc; MAP_OPTS="-aps sensor"; PHOTONS=2m; PHOTONS_LIGHT=200k
K=10000; K_LIGHT=500
RENDER="-ab 0"
LIGHT_POINTS="1 3 5"
