// The ray state a .cal function sees: RADIANCE's predefined variables (Dx..Kz, T, Rdot,
// ...) as plain doubles the renderer fills in, plus the modifier's real arguments (A1..An,
// arg(n)). Computing these values (object-space transforms, ray lengths) is the
// renderer's job; the evaluator only reads them through slots resolved at compile time.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <type_traits>

#include "util/vec.h"

namespace rp::calc {

// Values in the modifier's object space (ray.html, "Function Files"): a modifier's
// transform arguments (-t -rx -ry -rz -s -mx -my -mz -i) change the space in which
// P, D and N are seen; S and the I/J/K axes describe that space in world terms.
struct RayContext {
    Vec3 D{0, 0, 1};  // Dx Dy Dz: ray direction (unit in world space, divided by S)
    Vec3 N{0, 0, 1};  // Nx Ny Nz: surface normal (divided by S)
    Vec3 P;           // Px Py Pz: intersection point
    double Lu = 0;    // Lu: local u coordinate (meshes)
    double Lv = 0;    // Lv: local v coordinate (meshes)
    double T = 0;     // T: distance from the ray's origin (eye) to P, times S
    double Ts = 0;    // Ts: length of this single ray segment (shadow-ray distance)
    double Rdot = 0;  // Rdot: cosine between the ray and the surface normal (-D.N)
    double S = 1;     // S: world scale of the object space
    Vec3 Tvec;        // Tx Ty Tz: world origin as seen in object space
    Vec3 I{1, 0, 0};  // Ix Iy Iz: world i unit vector in object space
    Vec3 J{0, 1, 0};  // Jx Jy Jz
    Vec3 K{0, 0, 1};  // Kx Ky Kz
    // Set for *func, *data and BRTDfunc materials only (m_brdf.c setbrdfunc; 0 elsewhere):
    Vec3 NP{0, 0, 1};  // NxP NyP NzP: perturbed normal on the ray's side, as N
    double RdotP = 0;  // RdotP: -D.NP in world space, clamped to [-1, 1]
    Vec3 CP;           // CrP CgP CbP: the material colour times the pattern
                       // (*func/*data), the pattern alone (BRTDfunc)
    // DxA DyA DzA (prism1/prism2, m_direct.c): unit direction from P to the light source
    // a redirected ray is aimed at, seen like D; zero for rays not aimed at a source.
    Vec3 DA;
    std::span<const double> args;  // the modifier's real arguments: A1 = args[0], arg(0) = size
};

static_assert(std::is_standard_layout_v<RayContext>);

// One predefined ray variable: its name and where its double lives in RayContext.
struct RayVariable {
    std::string_view name;
    std::size_t offset;  // byte offset of the double inside RayContext
};

// All predefined ray variables (Dx Dy Dz Nx Ny Nz Px Py Pz Lu Lv T Ts Rdot S Tx Ty Tz
// Ix Iy Iz Jx Jy Jz Kx Ky Kz NxP NyP NzP RdotP CrP CgP CbP DxA DyA DzA). A1..An come from
// rayinit.cal (A1 = arg(1); ...).
std::span<const RayVariable> rayVariables();

// Reads the variable at `offset` (from rayVariables()).
inline double rayValue(const RayContext& ctx, std::size_t offset) {
    return *reinterpret_cast<const double*>(reinterpret_cast<const char*>(&ctx) + offset);
}

}  // namespace rp::calc
