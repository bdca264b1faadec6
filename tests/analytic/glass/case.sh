# glass: classic -ab 0 (the shadow ray passes the glass with its transmittance);
# photon map: caustic photons from the pane as port, -ab 0 (shadow rays through glass
# then leave the light to the caustic photons).
CLASSIC="-ab 0 -dj 1"
MAP=-apc; MAP_OPTS="-apo pane -aps sensor"; PHOTONS=2m; PHOTONS_LIGHT=200k
K=10000; K_LIGHT=500
RENDER="-ab 0"
LIGHT_POINTS="1 2 3"
