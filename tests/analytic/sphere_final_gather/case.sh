# sphere_final_gather: the photon map as it is used for rendering: one final-gather
# bounce (-ab 1, no cache: repeats independent) onto global photons. Classic as
# integrating_sphere; the lamp's shadow bias (4e-4) applies to the photon part too.
CLASSIC="-ab 12 -aa 0 -ad 512 -as 0 -lw 1e-5"
CLASSIC_BIAS=6.4e-4
MAP=-apg; PHOTONS=1m; PHOTONS_LIGHT=200k
K=1000; K_LIGHT=200
RENDER="-ab 1 -aa 0 -ad 1024 -as 0"
PMAP_REPS=16; PMAP_REPS_LIGHT=8
PMAP_BIAS=4e-4
LIGHT_POINTS="1 2 3"
