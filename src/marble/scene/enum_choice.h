#pragma once
// The names of an enum's values, one table per enum: what files and the command line accept
// and what is written back (`name`), what the panel's combos show (`label`), and the lists that
// messages and help texts offer. Parsing, printing, help and combos all read the table, so a
// value is named in one place. The material's enums are in material_params.cpp; the scene's
// below (scene_enums.cpp).
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace marble {

struct EnumChoice {
  int value;
  const char* name;
  const char* label;
};

// The entry named exactly `name`, or null.
const EnumChoice* findChoice(std::span<const EnumChoice> table, std::string_view name);
// The name of `value`; "" if the table has none.
const char* choiceName(std::span<const EnumChoice> table, int value);
// The names as a message offers them, in table order: `"a" or "b"`, `"a", "b" or "c"` (quoted),
// `a or b` (not).
std::string choiceAlternatives(std::span<const EnumChoice> table, bool quoted = true);
// The names in table order.
std::vector<std::string> choiceNames(std::span<const EnumChoice> table);
// The labels indexed by value (0, 1, ...: the values must be exactly those), for a combo box.
std::vector<const char*> choiceLabelsByValue(std::span<const EnumChoice> table);

// The scene's enums (scene.h), each in the order its messages list it.
std::span<const EnumChoice> renderModeChoices();
std::span<const EnumChoice> environmentChoices();
std::span<const EnumChoice> subsurfaceResolutionChoices();
std::span<const EnumChoice> antialiasChoices();
std::span<const EnumChoice> lightTypeChoices();

}  // namespace marble
