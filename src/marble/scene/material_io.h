#pragma once
// Materials as JSON: the built-in presets (presets/*.json, embedded at build time), preset files,
// scene overrides ("material": {"preset": "calacatta", "vein_color": [...]}) and `--set key=value`.
// Every field of Material has one flat key (materialKeys(); documented in docs/materials.md).
// Wrong types and out-of-range values throw InputError naming the file and the key; unknown keys
// are warnings.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "marble/scene/material.h"

namespace marble {

struct PresetInfo {
  std::string name, description;
};

// The embedded presets, sorted by name.
std::vector<PresetInfo> builtinPresets();

// A built-in preset by name ("carrara"), or a path to a .json material file. Throws InputError.
// Unknown keys in the file are appended to `warnings` if given, else printed to stderr.
Material loadPreset(const std::string& nameOrPath, std::vector<std::string>* warnings = nullptr);

// Applies a JSON object to `m`: "preset" (if present) first replaces m by that preset, then every
// other key overrides. `file` names the source for messages, `placePrefix` is put before the key
// ("material." in a scene). Errors: InputError(file, placePrefix + key, "expected ..., got ...").
// Unknown keys: "file: place: unknown key 'x' (ignored)" appended to `warnings`.
void applyMaterialJson(Material& m, const nlohmann::json& j, const std::string& file, const std::string& placePrefix,
                       std::vector<std::string>& warnings);

// `--set key=value`: value is a number, "r,g,b", or a name (enums, name, description).
// Errors: InputError("--set", key, problem).
void setMaterialKey(Material& m, const std::string& key, const std::string& value);

// Every key; applyMaterialJson(materialToJson(m)) reproduces m exactly (bit for bit).
nlohmann::json materialToJson(const Material& m);
void saveMaterial(const std::filesystem::path& path, const Material& m);  // atomic; throws InputError

// All keys in file order (name, description, pattern, colour, subsurface, reflectance, comparison).
std::vector<std::string> materialKeys();

// Cross-field check (turb_size <= resolution). Throws InputError(file, placePrefix + key, ...).
void validateMaterial(const Material& m, const std::string& file, const std::string& placePrefix);

}  // namespace marble
