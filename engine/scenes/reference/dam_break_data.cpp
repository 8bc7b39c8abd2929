#include "dam_break_data.h"

#include <limits>

namespace sph::scenes {
namespace {

constexpr std::pair<double, double> kMartinMoyce[] = {
    {0.849, 1.245}, {1.212, 1.443}, {1.602, 1.884}, {2.283, 2.689}, {2.950, 3.728},
    {3.598, 4.528}, {3.905, 4.999}, {4.592, 5.841}, {4.961, 6.271}, {5.316, 6.717}};
constexpr std::pair<double, double> kKoshizukaOka[] = {
    {0.0, 1.0},     {0.381, 1.111}, {0.769, 1.252}, {1.153, 1.505}, {1.537, 1.892},
    {1.935, 2.241}, {2.323, 2.615}, {2.719, 3.003}, {3.096, 3.624}};

}  // namespace

std::span<const std::pair<double, double>> martin_moyce_front() { return kMartinMoyce; }
std::span<const std::pair<double, double>> koshizuka_oka_front() { return kKoshizukaOka; }

double interpolate_front(std::span<const std::pair<double, double>> data, double T) {
  if (data.empty() || T < data.front().first || T > data.back().first) return std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 1; k < data.size(); ++k)
    if (T <= data[k].first) {
      const auto [t0, z0] = data[k - 1];
      const auto [t1, z1] = data[k];
      return z0 + (z1 - z0) * (T - t0) / (t1 - t0);
    }
  return data.back().second;
}

}  // namespace sph::scenes
