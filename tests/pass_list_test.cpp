// The list of passes (render/pass_list.h): one entry per pass in frame order, names the
// benchmark's JSON can key on, and declarations the caching rule can rely on.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "marble/render/pass_list.h"

using namespace marble;

namespace {
Scene sceneIn(RenderMode mode) {
  Scene s;
  s.render.mode = mode;
  return s;
}
}  // namespace

TEST(PassList, OneEntryPerPassWithDistinctNames) {
  std::set<std::string> names, labels;
  ASSERT_EQ(passList().size(), kPassCount);
  for (const PassDecl& d : passList()) {
    EXPECT_EQ(&passDecl(d.pass), &d);
    EXPECT_TRUE(names.insert(d.name).second) << d.name;
    EXPECT_TRUE(labels.insert(d.label).second) << d.label;
    for (char c : std::string(d.name)) EXPECT_TRUE((c >= 'a' && c <= 'z') || c == '_') << d.name << ": a JSON key";
    EXPECT_NE(std::string(d.what), "");
  }
}

// PassCache compares a pass's groups in the frame's mode; that is right only if a pass that
// does not declare the mode reads the same groups in every mode its output is made in. (The
// albedo is also made by `marble`'s post pass.)
TEST(PassList, APassThatIgnoresTheModeReadsTheSameGroupsInEveryMode) {
  int checked = 0;
  for (const PassDecl& d : passList()) {
    if (d.everyFrame || (d.inputs & inputBit(PassInput::Mode)) != 0) continue;
    std::set<GroupSet> seen;
    for (size_t m = 0; m < renderModeNames().size(); ++m) {
      const RenderMode mode = static_cast<RenderMode>(m);
      if (passInFrame(d.pass, sceneIn(mode)) || (d.pass == Pass::Albedo && mode == RenderMode::Marble))
        seen.insert(passGroups(d.pass, mode));
    }
    EXPECT_EQ(seen.size(), 1u) << d.name;
    ++checked;
  }
  EXPECT_GE(checked, 4);  // light depth, geometry, albedo, blur depth, subsurface blur
}

// Every role in which material_params.cpp says a parameter is read is a pass's: no parameter
// is read by no pass (its change would re-run nothing).
TEST(PassList, EveryParameterIsReadByADeclaredPass) {
  uint32_t roles = 0;
  for (const PassDecl& d : passList()) roles |= d.params | d.marbleParams;
  for (const ParamDesc& p : materialParams()) EXPECT_EQ(p.passes & ~roles, 0u) << p.key;
  EXPECT_NE(passGroups(Pass::Lighting, RenderMode::Paper) & groupBit(ParamGroup::PaperModel), 0u);
  EXPECT_EQ(passGroups(Pass::Lighting, RenderMode::Marble) & groupBit(ParamGroup::PaperModel), 0u);
  EXPECT_NE(passGroups(Pass::Post, RenderMode::Marble) & groupBit(ParamGroup::Pattern), 0u)
      << "marble's post pass evaluates the pattern";
  EXPECT_EQ(passGroups(Pass::Post, RenderMode::Paper) & groupBit(ParamGroup::Pattern), 0u);
}

TEST(PassList, TheFrameHasThePassesItsSettingsAskFor) {
  auto inFrame = [](const Scene& s) {
    std::string list;
    for (const PassDecl& d : passList())
      if (passInFrame(d.pass, s)) list += std::string(list.empty() ? "" : " ") + d.name;
    return list;
  };
  Scene s = sceneIn(RenderMode::Marble);
  EXPECT_EQ(inFrame(s), "light_depth geometry blur_depth bounce lighting subsurface_blur post fxaa");
  s.render.subsurface_resolution = SubsurfaceResolution::Full;
  s.render.antialias = Antialias::None;
  s.render.backdrop = true;
  EXPECT_EQ(inFrame(s), "light_depth geometry bounce lighting subsurface_blur post stage");
  EXPECT_EQ(inFrame(sceneIn(RenderMode::Paper)), "light_depth geometry albedo lighting post fxaa");
  EXPECT_EQ(inFrame(sceneIn(RenderMode::Normal)), "light_depth geometry lighting post fxaa");
  EXPECT_EQ(inFrame(sceneIn(RenderMode::Floor)), "floor");
  // The lighting pass reads the albedo where the mode shades with it, the blur's depth in `marble`.
  EXPECT_NE(passReads(Pass::Lighting, sceneIn(RenderMode::Paper)) & passBit(Pass::Albedo), 0u);
  EXPECT_EQ(passReads(Pass::Lighting, sceneIn(RenderMode::Marble)) & passBit(Pass::Albedo), 0u);
  EXPECT_NE(passReads(Pass::Lighting, sceneIn(RenderMode::Marble)) & passBit(Pass::BlurDepth), 0u);
  // `marble`'s bounce: gathered from the light's map for the G-buffer's points, upsampled by the lighting.
  EXPECT_EQ(passReads(Pass::Bounce, sceneIn(RenderMode::Marble)), passBit(Pass::LightDepth) | passBit(Pass::Geometry));
  EXPECT_NE(passReads(Pass::Lighting, sceneIn(RenderMode::Marble)) & passBit(Pass::Bounce), 0u);
  EXPECT_EQ(passReads(Pass::Lighting, sceneIn(RenderMode::Paper)) & passBit(Pass::Bounce), 0u);
}

// The bounce's emitters have the stone's base colour, which the bounce pass's last draw applies
// (bounce_merge.frag.glsl): `marble`'s bounce reads the base colour and not the rest of the ramp (a
// vein colour must not re-run it, nor the lighting and the blur after it), and the lighting reads
// no colour at all (it takes the base colour through the bounce).
TEST(PassList, MarbleBounceReadsTheBaseColourAloneOfTheColours) {
  const GroupSet bounce = passGroups(Pass::Bounce, RenderMode::Marble);
  EXPECT_NE(bounce & groupBit(ParamGroup::BaseColour), 0u);
  EXPECT_EQ(bounce & groupBit(ParamGroup::Colour), 0u);
  EXPECT_EQ(passGroups(Pass::Lighting, RenderMode::Marble) & (groupBit(ParamGroup::BaseColour) | groupBit(ParamGroup::Colour)), 0u);
  EXPECT_NE(passGroups(Pass::Post, RenderMode::Marble) & groupBit(ParamGroup::Colour), 0u) << "the pattern's ramp";
  // And the base colour is alone in its group: the groups are what the cache compares.
  int inGroup = 0;
  for (const ParamDesc& p : materialParams()) inGroup += p.group == ParamGroup::BaseColour ? 1 : 0;
  EXPECT_EQ(inGroup, 1);
  EXPECT_EQ(findParam("base_color")->group, ParamGroup::BaseColour);
}

TEST(PassList, TheTooltipSaysWhatMakesAPassReRun) {
  const std::string lighting = passInputsText(Pass::Lighting, sceneIn(RenderMode::Marble));
  EXPECT_NE(lighting.find("the light"), std::string::npos) << lighting;
  EXPECT_NE(lighting.find("Scattering"), std::string::npos) << lighting;
  EXPECT_NE(lighting.find("light depth"), std::string::npos) << lighting;
  EXPECT_EQ(lighting.find("Gloss"), std::string::npos) << lighting;
  EXPECT_NE(passInputsText(Pass::Post, sceneIn(RenderMode::Marble)).find("every frame"), std::string::npos);
}
