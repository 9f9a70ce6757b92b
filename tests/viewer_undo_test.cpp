// The viewer's undo stack (src/marble/scene/undo_stack.h): one step per committed edit,
// undo restores the previous value exactly, redo re-applies, a new edit clears redo, capped.
#include <gtest/gtest.h>

#include "marble/scene/undo_stack.h"

namespace marble {
namespace {

EditState withTurbulence(float power) {
  EditState e;
  e.material.turb_power = power;
  return e;
}

TEST(ViewerUndo, NothingToUndoAtStart) {
  UndoStack stack;
  stack.reset(withTurbulence(1));
  EXPECT_FALSE(stack.canUndo());
  EXPECT_FALSE(stack.undo(withTurbulence(1)).has_value());
  EXPECT_FALSE(stack.redo(withTurbulence(1)).has_value());
}

TEST(ViewerUndo, CommitOfAnUnchangedStateIsNoStep) {
  UndoStack stack;
  stack.reset(withTurbulence(1));
  EXPECT_FALSE(stack.commit(withTurbulence(1)));
  EXPECT_EQ(stack.undoCount(), 0u);
}

TEST(ViewerUndo, UndoRestoresThePreviousValueAndRedoReappliesIt) {
  UndoStack stack;
  stack.reset(withTurbulence(1));
  EXPECT_TRUE(stack.commit(withTurbulence(2)));
  EXPECT_TRUE(stack.commit(withTurbulence(3)));
  auto back = stack.undo(withTurbulence(3));
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->material.turb_power, 2.0f);
  back = stack.undo(*back);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->material.turb_power, 1.0f);
  EXPECT_FALSE(stack.undo(*back).has_value());
  auto fwd = stack.redo(*back);
  ASSERT_TRUE(fwd.has_value());
  EXPECT_EQ(fwd->material.turb_power, 2.0f);
}

TEST(ViewerUndo, AnUncommittedEditIsUndoneToo) {
  // Ctrl+Z right after typing a value, before anything committed it.
  UndoStack stack;
  stack.reset(withTurbulence(1));
  const auto back = stack.undo(withTurbulence(7));
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->material.turb_power, 1.0f);
  const auto fwd = stack.redo(*back);
  ASSERT_TRUE(fwd.has_value());
  EXPECT_EQ(fwd->material.turb_power, 7.0f);
}

TEST(ViewerUndo, ANewEditClearsRedo) {
  UndoStack stack;
  stack.reset(withTurbulence(1));
  stack.commit(withTurbulence(2));
  const auto back = stack.undo(withTurbulence(2));
  ASSERT_TRUE(back.has_value());
  EXPECT_TRUE(stack.canRedo());
  stack.commit(withTurbulence(5));
  EXPECT_FALSE(stack.canRedo());
  EXPECT_FALSE(stack.redo(withTurbulence(5)).has_value());
}

TEST(ViewerUndo, EveryPartOfTheLookIsTracked) {
  const EditState base;
  EditState e = base;
  e.material.vein_color.g += 0.1f;
  EXPECT_FALSE(sameEdit(base, e));
  e = base;
  e.material.name = "other";
  EXPECT_FALSE(sameEdit(base, e));
  e = base;
  e.light.intensity = 2;
  EXPECT_FALSE(sameEdit(base, e));
  e = base;
  e.lightOrbit.yaw_deg = 30;
  EXPECT_FALSE(sameEdit(base, e));
  e = base;
  e.mode = RenderMode::Paper;
  EXPECT_FALSE(sameEdit(base, e));
  e = base;
  e.light.position = glm::vec3(9);  // the orbit holds the light's place; this copy is ignored
  EXPECT_TRUE(sameEdit(base, e));
}

TEST(ViewerUndo, HistoryIsCappedOldestFirst) {
  UndoStack stack(3);
  stack.reset(withTurbulence(0));
  for (int i = 1; i <= 5; ++i) stack.commit(withTurbulence(static_cast<float>(i)));
  EXPECT_EQ(stack.undoCount(), 3u);
  EditState now = withTurbulence(5);
  for (float expected : {4.0f, 3.0f, 2.0f}) {
    const auto back = stack.undo(now);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->material.turb_power, expected);
    now = *back;
  }
  EXPECT_FALSE(stack.undo(now).has_value());
}

}  // namespace
}  // namespace marble
