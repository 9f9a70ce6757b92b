// The enum name tables (scene/enum_choice.h): every name reads back as its value and is what is
// written; the lists that messages offer; the panel's labels by value.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "marble/scene/enum_choice.h"
#include "marble/scene/material_params.h"
#include "marble/scene/scene.h"

namespace marble {
namespace {

void expectWellFormed(std::span<const EnumChoice> table, const char* what) {
  std::set<int> values;
  std::set<std::string> names;
  for (const auto& e : table) {
    EXPECT_TRUE(values.insert(e.value).second) << what << ": value " << e.value << " twice";
    EXPECT_TRUE(names.insert(e.name).second) << what << ": name " << e.name << " twice";
    const EnumChoice* found = findChoice(table, e.name);
    ASSERT_NE(found, nullptr) << what << ": " << e.name;
    EXPECT_EQ(found->value, e.value);
    EXPECT_STREQ(choiceName(table, e.value), e.name);
  }
  // A combo indexes its labels by value: the values are 0..n-1.
  const auto labels = choiceLabelsByValue(table);
  for (size_t i = 0; i < labels.size(); ++i) EXPECT_STRNE(labels[i], "") << what << ": no value " << i;
}

TEST(EnumChoice, EverySceneTableReadsBackWhatItWrites) {
  expectWellFormed(renderModeChoices(), "render mode");
  expectWellFormed(environmentChoices(), "environment");
  expectWellFormed(subsurfaceResolutionChoices(), "subsurface resolution");
  expectWellFormed(antialiasChoices(), "antialias");
  expectWellFormed(lightTypeChoices(), "light type");
}

TEST(EnumChoice, TheMaterialsChoiceParametersAreWellFormedToo) {
  for (const auto& p : materialParams())
    if (p.type == ParamType::Choice) expectWellFormed(p.choices, p.key);
}

TEST(EnumChoice, UnknownNamesAreNotFound) {  // the negative control
  EXPECT_EQ(findChoice(antialiasChoices(), "FXAA"), nullptr) << "names are exact: the label is not a name";
  EXPECT_EQ(findChoice(environmentChoices(), ""), nullptr);
  EXPECT_STREQ(choiceName(lightTypeChoices(), 99), "");
}

TEST(EnumChoice, MessagesOfferTheNamesInTableOrder) {
  EXPECT_EQ(choiceAlternatives(environmentChoices()), R"("studio", "none" or "map")");
  EXPECT_EQ(choiceAlternatives(antialiasChoices()), R"("fxaa" or "none")");
  EXPECT_EQ(choiceAlternatives(subsurfaceResolutionChoices(), false), "half or full");
  EXPECT_EQ(choiceAlternatives(lightTypeChoices()), R"("point" or "directional")");
}

TEST(EnumChoice, TheSceneFunctionsUseTheTables) {
  for (size_t i = 0; i < renderModeNames().size(); ++i) {
    EXPECT_EQ(renderModeNames()[i], renderModeChoices()[i].name);
    EXPECT_EQ(parseRenderMode(renderModeNames()[i]), static_cast<RenderMode>(i));
  }
  EXPECT_EQ(renderModeNames().size(), renderModeChoices().size());
  EXPECT_EQ(parseEnvironment("map"), Environment::Map);
  EXPECT_EQ(parseAntialias("none"), Antialias::None);
  EXPECT_STREQ(antialiasName(Antialias::Fxaa), "fxaa");
  const auto labels = choiceLabelsByValue(antialiasChoices());
  EXPECT_STREQ(labels[static_cast<size_t>(Antialias::Fxaa)], "FXAA");
}

}  // namespace
}  // namespace marble
