// Names of the kernel, integrator and softening choices (used by JSON files, --set and the GUI).
#include "sph/params.h"

namespace sph {
namespace {

template <class E, std::size_t N>
bool parse_enum(const std::string& s, E& out, const std::pair<const char*, E> (&table)[N]) {
  for (const auto& [name, value] : table)
    if (s == name) { out = value; return true; }
  return false;
}

constexpr std::pair<const char*, KernelType> kKernels[] = {
    {"M4", KernelType::M4}, {"M5", KernelType::M5}, {"M6", KernelType::M6},
    {"gaussian", KernelType::Gaussian}, {"wendland_c2", KernelType::WendlandC2},
    {"wendland_c4", KernelType::WendlandC4}};
constexpr std::pair<const char*, IntegratorType> kIntegrators[] = {
    {"euler", IntegratorType::Euler}, {"rk4", IntegratorType::RK4},
    {"leapfrog", IntegratorType::Leapfrog}, {"predictor_corrector", IntegratorType::PredictorCorrector}};

constexpr std::pair<const char*, Softening> kSoftenings[] = {
    {"plummer", Softening::Plummer}, {"kernel", Softening::Kernel}, {"kernel_no_grad_h", Softening::KernelNoGradH}};
constexpr std::pair<const char*, PointControl> kControls[] = {{"none", PointControl::None},
                                                             {"reinterpolate", PointControl::Reinterpolate},
                                                             {"merge_split", PointControl::MergeSplit}};

constexpr std::pair<const char*, ViscSwitch> kSwitches[] = {
    {"none", ViscSwitch::None}, {"balsara", ViscSwitch::Balsara}, {"cullen_dehnen", ViscSwitch::CullenDehnen}};

constexpr std::pair<const char*, DfsphSolverType> kDfsphSolvers[] = {{"jacobi", DfsphSolverType::Jacobi},
                                                                    {"bicgstab", DfsphSolverType::BiCGStab}};

template <class E, std::size_t N>
const char* name_of(E e, const std::pair<const char*, E> (&table)[N]) {
  for (const auto& [name, value] : table)
    if (value == e) return name;
  return "?";
}

}  // namespace

const char* to_string(KernelType k) { return name_of(k, kKernels); }
const char* to_string(IntegratorType i) { return name_of(i, kIntegrators); }
bool parse(const std::string& s, KernelType& out) { return parse_enum(s, out, kKernels); }
bool parse(const std::string& s, IntegratorType& out) { return parse_enum(s, out, kIntegrators); }
const char* to_string(Softening s) { return name_of(s, kSoftenings); }
bool parse(const std::string& s, Softening& out) { return parse_enum(s, out, kSoftenings); }
const char* to_string(PointControl c) { return name_of(c, kControls); }
bool parse(const std::string& s, PointControl& out) { return parse_enum(s, out, kControls); }
const char* to_string(ViscSwitch s) { return name_of(s, kSwitches); }
bool parse(const std::string& s, ViscSwitch& out) { return parse_enum(s, out, kSwitches); }
const char* to_string(DfsphSolverType s) { return name_of(s, kDfsphSolvers); }
bool parse(const std::string& s, DfsphSolverType& out) { return parse_enum(s, out, kDfsphSolvers); }

}  // namespace sph
