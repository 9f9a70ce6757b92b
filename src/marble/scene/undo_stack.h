#pragma once
// Undo/redo of the viewer's parameter edits. What is undoable is the "look" of the scene:
// the material, the light and the render mode; the camera is not (users orbit constantly and
// expect Ctrl+Z to undo a slider, not a glance). Pure data, no GL, no ImGui: unit-tested alone.
//
// The stack keeps the last committed state. The viewer calls commit(current) when an edit ends
// (a widget deactivated after an edit, a light drag released, a preset picked); if the state
// differs from the last committed one, that one goes onto the undo list. A drag of a slider is
// therefore one step, not one per frame.
#include <cstddef>
#include <deque>
#include <optional>

#include "marble/scene/orbit.h"
#include "marble/scene/scene.h"

namespace marble {

struct EditState {
  Material material;
  Light light;        // type, colour, intensity; its position is ignored (lightOrbit holds it)
  Orbit lightOrbit;   // the light's place as the viewer edits it (angles survive undo exactly)
  RenderMode mode = RenderMode::Marble;
};

// Equal in everything undo cares about (every material key, light type/colour/intensity,
// the light orbit, the mode).
bool sameEdit(const EditState& a, const EditState& b);

class UndoStack {
public:
  static constexpr size_t kDefaultCapacity = 200;
  explicit UndoStack(size_t capacity = kDefaultCapacity);

  // Starts over from `state`: no history, `state` is the committed one.
  void reset(const EditState& state);
  // Records `current` as a step if it differs from the committed state. Returns whether it did.
  // A new step clears the redo list; beyond the capacity the oldest step is forgotten.
  bool commit(const EditState& current);
  // The state to go back (or forward) to, which also becomes the committed one; nothing when
  // there is nothing to undo (redo). `current` is what is on screen now: if it holds an edit not
  // yet committed, that edit is what gets undone (and can be redone).
  std::optional<EditState> undo(const EditState& current);
  std::optional<EditState> redo(const EditState& current);

  bool canUndo() const { return !undo_.empty(); }
  bool canRedo() const { return !redo_.empty(); }
  size_t undoCount() const { return undo_.size(); }
  size_t redoCount() const { return redo_.size(); }
  const EditState& committed() const { return committed_; }

private:
  size_t capacity_;
  EditState committed_;
  std::deque<EditState> undo_, redo_;
};

}  // namespace marble
