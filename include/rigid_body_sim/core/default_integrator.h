// The scheme a World steps with unless told otherwise: the first row of
// IntegratorTable (integrator.h), named here alone so that a definition of
// settings can default to it without the schemes.
#pragma once

namespace rigid_body_sim::core {

inline constexpr char kDefaultIntegrator[] = "casimir_splitting4";

}  // namespace rigid_body_sim::core
