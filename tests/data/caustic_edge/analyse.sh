#!/bin/bash
# Errors of rtrace -I readings of sensors.sh's points against scene.rad's closed form.
#   analyse.sh LABELS RESULTS   (paste-able line for line; several runs: concatenate both)
# Prints per distance label t (cm, > 0 inside): "t mean_error rms_error n", the errors as
# fractions of the interior irradiance E0 (outside the rectangle the truth is 0, so errors
# relative to the local truth would not exist there); then "in mean/E0 rsd n" for the
# interior points, rsd their relative standard deviation (sd / mean).
# Closed form (scene.rad): E0 = L Omega cos 45, Omega = 2 pi (1 - cos alpha), alpha = 0.25
# deg; at t cm from the edge E = E0 A(t/100 cos 45 / (0.4 alpha)), A(d) = (pi - acos d +
# d sqrt(1 - d^2)) / pi for |d| < 1 (0 below, 1 above): the part of the sun's disc that
# the mirror's edge lets through.
set -u
paste -d' ' "$1" "$2" | awk '
function acos(x) { return atan2(sqrt(1 - x * x), x) }
function A(d) { if (d <= -1) return 0; if (d >= 1) return 1
    return (pi - acos(d) + d * sqrt(1 - d * d)) / pi }
BEGIN { pi = atan2(0, -1); a = 0.25 * pi / 180; e0 = 1e7 * 2 * pi * (1 - cos(a)) * sqrt(0.5) }
{ v = ($2 + $3 + $4) / 3
  if ($1 == "in") { n0++; s0 += v; q0 += v * v; next }
  t = $1; e = (v - e0 * A(t / 100 * sqrt(0.5) / (0.4 * a))) / e0
  n[t]++; s[t] += e; q[t] += e * e }
END { for (t in n) printf "%s %.4f %.4f %d\n", t, s[t] / n[t], sqrt(q[t] / n[t]), n[t] | "sort -g"
      close("sort -g")
      m = s0 / n0; printf "in %.4f %.4f %d\n", m / e0, sqrt(q0 / n0 - m * m) / m, n0 }'
