// The columns of a measured value, its exact counterpart and their relative error (compared_columns.h).
#include "reference/compared_columns.h"

#include <utility>

namespace sph::scenes {

std::vector<RefColumn> compared_columns(const std::string& name, std::string measured, std::string exact,
                                        std::string error_name, const std::string& note) {
  const std::string exact_name = name + "_exact";
  if (error_name.empty()) error_name = name + "_err";
  return {{name, std::move(measured), false},
          {exact_name, std::move(exact), false},
          {std::move(error_name), "|" + name + " / " + exact_name + " - 1|" + note, true}};
}

void append_columns(std::vector<RefColumn>& columns, const std::vector<RefColumn>& more) {
  columns.insert(columns.end(), more.begin(), more.end());
}

}  // namespace sph::scenes
