// Name table of the predefined ray variables (see ray_context.h).
#include "calc/ray_context.h"

#include <array>
#include <cstddef>

namespace rp::calc {
namespace {

#define RP_RAYVAR(name, member, k) \
    RayVariable { name, offsetof(RayContext, member) + (k) * sizeof(double) }

const std::array kRayVariables = {
    RP_RAYVAR("Dx", D, 0),        RP_RAYVAR("Dy", D, 1),      RP_RAYVAR("Dz", D, 2),
    RP_RAYVAR("Nx", N, 0),        RP_RAYVAR("Ny", N, 1),      RP_RAYVAR("Nz", N, 2),
    RP_RAYVAR("Px", P, 0),        RP_RAYVAR("Py", P, 1),      RP_RAYVAR("Pz", P, 2),
    RP_RAYVAR("Lu", Lu, 0),       RP_RAYVAR("Lv", Lv, 0),     RP_RAYVAR("T", T, 0),
    RP_RAYVAR("Ts", Ts, 0),       RP_RAYVAR("Rdot", Rdot, 0), RP_RAYVAR("S", S, 0),
    RP_RAYVAR("Tx", Tvec, 0),     RP_RAYVAR("Ty", Tvec, 1),   RP_RAYVAR("Tz", Tvec, 2),
    RP_RAYVAR("Ix", I, 0),        RP_RAYVAR("Iy", I, 1),      RP_RAYVAR("Iz", I, 2),
    RP_RAYVAR("Jx", J, 0),        RP_RAYVAR("Jy", J, 1),      RP_RAYVAR("Jz", J, 2),
    RP_RAYVAR("Kx", K, 0),        RP_RAYVAR("Ky", K, 1),      RP_RAYVAR("Kz", K, 2),
    RP_RAYVAR("NxP", NP, 0),      RP_RAYVAR("NyP", NP, 1),    RP_RAYVAR("NzP", NP, 2),
    RP_RAYVAR("RdotP", RdotP, 0), RP_RAYVAR("CrP", CP, 0),    RP_RAYVAR("CgP", CP, 1),
    RP_RAYVAR("CbP", CP, 2),      RP_RAYVAR("DxA", DA, 0),    RP_RAYVAR("DyA", DA, 1),
    RP_RAYVAR("DzA", DA, 2),
};

#undef RP_RAYVAR

}  // namespace

std::span<const RayVariable> rayVariables() { return kRayVariables; }

}  // namespace rp::calc
