// Which fields each physics module needs: a scene allocates only their union.
#include "sph/scene.h"

namespace sph {

FieldSet fields_for(const Modules& m) {
  FieldSet f;
  f.add(Field::Mass).add(Field::H).add(Field::Density).add(Field::Omega).add(Field::Neighbours).add(Field::HIterations);
  if (m.hydro) f.add(Field::Pressure).add(Field::SoundSpeed).add(Field::SignalSpeed);
  if (m.energy) f.add(Field::Energy).add(Field::EnergyRate);
  return f;
}

SceneValues SceneSpec::default_values() const {
  SceneValues v;
  for (const auto& p : params) v[p.name] = p.value;
  return v;
}

}  // namespace sph
