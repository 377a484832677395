#include "rigid_body_sim/core/reference/carlson.h"

#include <cmath>
#include <limits>

#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>

namespace rigid_body_sim::core {
namespace {

namespace policies = boost::math::policies;

// NaN (or the series' last value) where Boost cannot evaluate, never an
// exception: nothing throws through a simulation step.
using NanOnError = policies::policy<policies::domain_error<policies::ignore_error>,
                                    policies::pole_error<policies::ignore_error>,
                                    policies::overflow_error<policies::ignore_error>,
                                    policies::evaluation_error<policies::ignore_error>,
                                    policies::max_series_iterations<kMaxCarlsonSteps>>;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

double CarlsonRF(double x, double y, double z) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return kNaN;
  return boost::math::ellint_rf(x, y, z, NanOnError());
}

double CarlsonRJ(double x, double y, double z, double p) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z) || !std::isfinite(p)) {
    return kNaN;
  }
  return boost::math::ellint_rj(x, y, z, p, NanOnError());
}

}  // namespace rigid_body_sim::core
