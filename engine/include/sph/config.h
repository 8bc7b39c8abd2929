// A resolved run configuration: a scene, its run parameters (its physics included) and its own
// parameters, built from a scene name or a JSON scene file plus --set overrides. Invalid input throws
// ConfigError naming the file and key; nothing has been written at that point.
#pragma once
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include "sph/params.h"
#include "sph/scene.h"

namespace sph {

struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct RunConfig {
  const SceneSpec* scene = nullptr;
  /// A scene made at run time (an HDF5 initial condition): `scene` points into it, copies share it.
  std::shared_ptr<const SceneSpec> owned_scene;
  /// The file an initial-condition scene was read from (absolute): the "scene" of to_json().
  std::string source_file;
  Params params;
  SceneValues values;
  /// Run-parameter keys set explicitly (by a file or --set), with where: checked by validate().
  std::map<std::string, std::string> explicit_keys;

  /// Defaults of a built-in scene.
  static RunConfig from_scene(const std::string& name);
  /// A JSON file {"scene": NAME, "params": {key: value, ...}} (keys as in set()). Call validate()
  /// once every override is applied.
  static RunConfig from_file(const std::string& path);
  /// The same from JSON text; `origin` names where it came from in messages.
  static RunConfig from_json_text(const std::string& text, const std::string& origin);
  /// A built-in name, an HDF5 initial condition (.hdf5, .h5: load_hdf5_ic) or, if it ends in .json or
  /// names an existing file, a scene file.
  static RunConfig load(const std::string& name_or_file);

  /// Override one parameter: a run parameter key (param_table, or its old flat alias) or
  /// "scene.<name>". `origin` names the file or flag in error messages.
  void set(const std::string& key, const std::string& value, const std::string& origin);

  /// After all overrides: the physics is a valid combination the scene accepts, and every key set
  /// explicitly belongs to a stage the scene runs. Throws ConfigError naming the key and the stage.
  void validate() const;

  /// Every parameter of the scene's stages as resolved (defaults included), as JSON text.
  std::string to_json() const;
};

/// The physics is valid and accepted by the scene; throws ConfigError otherwise (World checks this).
void check_physics(const SceneSpec& scene, const Physics& physics);

}  // namespace sph
