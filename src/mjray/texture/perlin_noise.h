#pragma once
/// Ken Perlin's improved gradient noise (SIGGRAPH 2002) and the sums of octaves built on it.

namespace mjray {

/// Improved noise at (x, y, z): equal to Perlin's Java reference implementation (same
/// permutation table, fade 6t⁵ − 15t⁴ + 10t³, 12 gradient directions), in about [−1, 1],
/// 0 at every integer lattice point. Non-finite input gives 0.
double perlin_noise(double x, double y, double z);

/// Perlin's (1985) turbulence: Σ_{i<octaves} |noise(2ⁱ·p)| / 2ⁱ, non-negative and below about 2.
double perlin_turbulence(double x, double y, double z, int octaves);

/// Fractal sum (Hugo Elias' "Perlin noise", persistence ½): Σ_{i<octaves} noise(2ⁱ·p) / 2ⁱ.
double perlin_fractal(double x, double y, double z, int octaves);

}  // namespace mjray
