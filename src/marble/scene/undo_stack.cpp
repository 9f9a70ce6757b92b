#include "marble/scene/undo_stack.h"

#include "marble/scene/material_io.h"

namespace marble {

bool sameEdit(const EditState& a, const EditState& b) {
  // The JSON form covers every material key, so a field added to Material is compared
  // without anyone remembering to update this function.
  return a.mode == b.mode && a.light.type == b.light.type && a.light.color == b.light.color &&
         a.light.intensity == b.light.intensity && a.lightOrbit.yaw_deg == b.lightOrbit.yaw_deg &&
         a.lightOrbit.pitch_deg == b.lightOrbit.pitch_deg && a.lightOrbit.distance == b.lightOrbit.distance &&
         a.lightOrbit.target == b.lightOrbit.target && materialToJson(a.material) == materialToJson(b.material);
}

UndoStack::UndoStack(size_t capacity) : capacity_(capacity == 0 ? 1 : capacity) {}

void UndoStack::reset(const EditState& state) {
  committed_ = state;
  undo_.clear();
  redo_.clear();
}

bool UndoStack::commit(const EditState& current) {
  if (sameEdit(current, committed_)) return false;
  undo_.push_back(committed_);
  if (undo_.size() > capacity_) undo_.pop_front();
  redo_.clear();
  committed_ = current;
  return true;
}

std::optional<EditState> UndoStack::undo(const EditState& current) {
  commit(current);  // an edit still in progress (e.g. typed, not yet confirmed) is a step too
  if (undo_.empty()) return std::nullopt;
  redo_.push_back(committed_);
  committed_ = undo_.back();
  undo_.pop_back();
  return committed_;
}

std::optional<EditState> UndoStack::redo(const EditState& current) {
  if (!sameEdit(current, committed_)) {
    // Something changed since the last undo: that change is the newest history, redo is gone.
    commit(current);
    return std::nullopt;
  }
  if (redo_.empty()) return std::nullopt;
  undo_.push_back(committed_);
  if (undo_.size() > capacity_) undo_.pop_front();
  committed_ = redo_.back();
  redo_.pop_back();
  return committed_;
}

}  // namespace marble
