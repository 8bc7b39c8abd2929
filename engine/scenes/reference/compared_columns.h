// A measured value beside its exact counterpart and their relative error: the three columns of errors.csv
// ("X", "X_exact" and |X / X_exact - 1|) that several references report, described and computed by one rule.
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "sph/reference.h"

namespace sph::scenes {

/// Columns `name` (the measurement), `name`_exact and the error norm "|name / name_exact - 1|" + `note`,
/// named `error_name` (name_err when empty). Their values: x, exact, relative_error(x, exact).
std::vector<RefColumn> compared_columns(const std::string& name, std::string measured, std::string exact,
                                        std::string error_name = {}, const std::string& note = {});

/// The relative error |x / exact - 1|.
inline double relative_error(double x, double exact) { return std::abs(x / exact - 1.0); }

/// Appends `more` to `columns`.
void append_columns(std::vector<RefColumn>& columns, const std::vector<RefColumn>& more);

}  // namespace sph::scenes
