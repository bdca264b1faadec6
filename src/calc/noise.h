// The renderer's noise functions as RADIANCE defines them (ray.html, "Functions":
// noise3, noise3x/y/z, fnoise3), value for value, so that patterns built on them
// (stucco, marble, turbulence) look the same as in RADIANCE. Wrapped as builtins in builtins.cpp.
#pragma once

namespace rp::calc {

// Perlin's improved gradient noise (Perlin 2002, "Improving Noise"), in about [-1,1].
double noise3(double x, double y, double z);
// RADIANCE's noise3x/y/z: the partial derivative of noise3 along `axis` (0, 1, 2), taken
// as a backward difference over RADIANCE's step of 0.0005, not analytically.
double noise3Partial(double x, double y, double z, int axis);
// RADIANCE's fractal noise fnoise3: midpoint displacement on a lattice of step 1/2000,
// seeded by an integer hash of the lattice points; in about [-1,1], piecewise constant
// on cells of 1/2000.
double fnoise3(double x, double y, double z);

}  // namespace rp::calc
