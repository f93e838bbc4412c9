#pragma once
// Named solid materials with cited parameters, and one explicit name → factory table.
#include <string>
#include <vector>

#include "shockfield/materials/solid_material.hpp"

namespace shockfield::materials {

/// Aluminium of the paper's MPM studies (Xu et al. 2015, §4.1): E = 69 GPa (printed "Mpa", a typo),
/// ν = 0.33, ρ0 = 2700 kg/m³, σ_Y0 = 120 MPa, E_tan = 384 MPa, k = 237 W/(m·K), c0 = 5.35 km/s,
/// λ = 1.34, c_v = 880 J/(kg·K), γ0 = 1.96 (valid below 270 GPa), T0 = 300 K.
SolidMaterial aluminium_seed000();

/// OFHC copper. Hugoniot and Grüneisen from Steinberg, "Equation of state and strength properties
/// of selected materials", LLNL UCRL-MA-106439 (1996): ρ0 = 8930 kg/m³, c0 = 3940 m/s,
/// λ = 1.489, γ0 = 2.02, G0 = 47.7 GPa, Y0 = 120 MPa, Y_max = 640 MPa (hardening
/// Y0(1 + 36ε̄p)^0.45). E_tan = 470 MPa is the secant of that curve from Y0 to Y_max (reached at
/// ε̄p = 1.11). ν = 0.34, c_v = 385 J/(kg·K) and k = 401 W/(m·K) from the CRC Handbook of
/// Chemistry and Physics (97th ed.) at 298 K; E = 2G0(1 + ν) = 127.8 GPa.
SolidMaterial copper();

/// Linear bulk response P = K(1 − ρ0/ρ) (Mie-Grüneisen with λ = 0, γ0 = 0, c0 = √(K/ρ0)) and J2
/// strength from E, ν: the textbook elastic-plastic solid of uniaxial-strain wave analyses.
/// Temperature uses c_v = 900 J/(kg·K) (only for reporting).
SolidMaterial elastic_plastic(const std::string& name, double rho0, double young, double poisson,
                              double yield0, double tangent = 0.0);

/// Names accepted by make_material, in a fixed order.
std::vector<std::string> material_names();
/// The named material; InputError listing the known names when `name` is unknown.
SolidMaterial make_material(const std::string& name);

}  // namespace shockfield::materials
