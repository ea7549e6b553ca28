// SceneBuilder's instancing: ObjectBegin/ObjectEnd record the requests of an object, and
// ObjectInstance replays them with the current attributes and transform (the graphics state
// itself lives in scene_builder.cpp).
#include "core/scene/builder/scene_builder.h"

#include <algorithm>

namespace darc {

bool SceneBuilder::record(std::function<void(SceneBuilder&)> call) {
  if (!recording_) return false;
  recording_->push_back(std::move(call));
  return true;
}

void SceneBuilder::object_begin(const std::string& handle, const SourceLoc& loc) {
  if (recording_) throw RibError("ObjectBegin cannot nest");
  push_block(Block::Object, loc);
  recording_ = &objects_[handle];
  recording_->clear();
}

void SceneBuilder::object_end(const SourceLoc& loc) {
  pop_block(Block::Object, "ObjectEnd", loc);
  recording_ = nullptr;
}

void SceneBuilder::object_instance(const std::string& handle, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.object_instance(handle, loc); })) return;
  auto it = objects_.find(handle);
  if (it == objects_.end()) throw RibError("unknown object handle \"" + handle + "\"");
  if (replaying_) throw RibError("ObjectInstance inside an object is not supported");
  replaying_ = true;
  // The object's requests run in their own attribute scope, with the current attributes.
  Attributes saved_attr = attributes_;
  Matrix4 saved_ctm = ctm_;
  std::vector<TransformKey> saved_ctm_keys = ctm_keys_;
  const size_t depth = blocks_.size(), saved_attr_depth = saved_attributes_.size(), saved_ctm_depth = saved_ctm_.size();
  // A recorded request with an error is reported at the instance and skipped, like any other
  // request; the object's other requests still build.
  for (auto& call : it->second) {
    try {
      call(*this);
    } catch (const RibError& e) {
      diag_.error(loc, "ObjectInstance", "object \"" + handle + "\": " + e.what());
    }
  }
  replaying_ = false;
  // Blocks the object left open close with it.
  blocks_.resize(std::min(blocks_.size(), depth));
  block_locs_.resize(blocks_.size());
  saved_attributes_.resize(std::min(saved_attributes_.size(), saved_attr_depth));
  saved_ctm_.resize(std::min(saved_ctm_.size(), saved_ctm_depth));
  saved_ctm_keys_.resize(saved_ctm_.size());
  attributes_ = saved_attr;
  ctm_ = saved_ctm;
  ctm_keys_ = std::move(saved_ctm_keys);
}

}  // namespace darc
