#include "marble/scene/enum_choice.h"

namespace marble {

const EnumChoice* findChoice(std::span<const EnumChoice> table, std::string_view name) {
  for (const auto& e : table)
    if (name == e.name) return &e;
  return nullptr;
}

const char* choiceName(std::span<const EnumChoice> table, int value) {
  for (const auto& e : table)
    if (e.value == value) return e.name;
  return "";
}

std::string choiceAlternatives(std::span<const EnumChoice> table, bool quoted) {
  std::string out;
  for (size_t i = 0; i < table.size(); ++i) {
    if (i > 0) out += i + 1 == table.size() ? " or " : ", ";
    out += quoted ? "\"" + std::string(table[i].name) + "\"" : std::string(table[i].name);
  }
  return out;
}

std::vector<const char*> choiceLabelsByValue(std::span<const EnumChoice> table) {
  std::vector<const char*> labels(table.size(), "");
  for (const auto& e : table)
    if (e.value >= 0 && static_cast<size_t>(e.value) < labels.size()) labels[static_cast<size_t>(e.value)] = e.label;
  return labels;
}

std::vector<std::string> choiceNames(std::span<const EnumChoice> table) {
  std::vector<std::string> names;
  names.reserve(table.size());
  for (const auto& e : table) names.emplace_back(e.name);
  return names;
}

}  // namespace marble
