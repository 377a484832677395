// The first pass of XmlRpcFromYaml over libyaml's events, and what both
// passes share (yaml_passes.h).
#include "yaml_passes.h"

#include <cctype>

#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/yaml_value.h"

namespace rigid_body_sim::yaml_passes {
namespace {

using XmlRpc::XmlRpcValue;

// What a value costs once built, as glibc allocates for XmlRpcValue: the
// 16-byte value itself in its parent, plus what it owns on the heap.
constexpr std::size_t kSlotBytes = sizeof(XmlRpcValue);
constexpr std::size_t kStringBytes = 64;      // a new'd std::string, its buffer's header
constexpr std::size_t kCollectionBytes = 64;  // a new'd std::vector or std::map
constexpr std::size_t kMapMemberBytes = 80;   // a tree node with its key string

}  // namespace

std::string MiB(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

bool CertainlyNumber(const std::string& text) {
  if (text.empty() || text.size() > 32) return false;
  std::size_t i = (text[0] == '+' || text[0] == '-') ? 1 : 0;
  std::size_t digits = 0;
  for (; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i) ++digits;
  if (i < text.size() && text[i] == '.') {
    for (++i; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i) ++digits;
  }
  if (digits == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    std::size_t exponent_digits = 0;
    for (; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i)
      ++exponent_digits;
    if (exponent_digits == 0 || exponent_digits > 2) return false;
  }
  return i == text.size();
}

bool IsNull(const std::string& text) {
  return text.empty() || text == "~" || text == "null" || text == "Null" || text == "NULL";
}

void EventPass::Take(const Event& event) {
  switch (event.type) {
    case YAML_SCALAR_EVENT:
      if (TakesKey()) {
        Key(event.value);
      } else {
        Scalar(event);
      }
      break;
    case YAML_ALIAS_EVENT:
      if (TakesKey()) has_complex_key_ = true;
      Alias(event.anchor);
      break;
    case YAML_SEQUENCE_START_EVENT:
    case YAML_MAPPING_START_EVENT: {
      if (TakesKey()) has_complex_key_ = true;
      if (static_cast<int>(open_.size()) >= kMaxYamlDepth) {
        throw SceneError("YAML nested deeper than " + std::to_string(kMaxYamlDepth) +
                         " (the limit for a service text)");
      }
      const bool is_map = event.type == YAML_MAPPING_START_EVENT;
      Start(is_map, event.anchor);
      open_.push_back({is_map, true});
      break;
    }
    case YAML_SEQUENCE_END_EVENT:
    case YAML_MAPPING_END_EVENT:
      open_.pop_back();
      End();
      break;
    default:
      break;
  }
}

bool EventPass::TakesKey() {
  if (open_.empty() || !open_.back().is_map) return false;
  const bool key = open_.back().expects_key;
  open_.back().expects_key = !key;
  return key;
}

void SizingPass::Key(const std::string& key) { Charge(kMapMemberBytes + key.size()); }

void SizingPass::Scalar(const Event& event) {
  const bool owns_nothing = event.plain && (CertainlyNumber(event.value) || IsNull(event.value));
  Value(owns_nothing ? kSlotBytes : kSlotBytes + kStringBytes + event.value.size(), event.anchor);
}

void SizingPass::Alias(const std::string& anchor) {
  const auto anchored = anchored_bytes_.find(anchor);
  if (anchored == anchored_bytes_.end()) {
    throw SceneError("not valid YAML: the alias *" + anchor.substr(0, 64) +
                     " names no anchor before it");
  }
  Value(anchored->second, "");
}

void SizingPass::Start(bool /*is_map*/, const std::string& anchor) {
  CountInCollection();
  started_.push_back({total_bytes_, anchor});
  Charge(kSlotBytes + kCollectionBytes);
  open_collections_.push_back(collection_sizes_.size());
  collection_sizes_.push_back(0);
}

void SizingPass::End() {
  open_collections_.pop_back();
  const Started started = started_.back();
  started_.pop_back();
  if (!started.anchor.empty()) Anchor(started.anchor, total_bytes_ - started.bytes_before);
}

void SizingPass::Charge(std::size_t bytes) {
  if (bytes > kMaxYamlValueBytes - total_bytes_) {
    throw SceneError("the YAML text expands to more than " + MiB(kMaxYamlValueBytes) +
                     " of values, aliases counted at every use (the limit for a service text)");
  }
  total_bytes_ += bytes;
}

void SizingPass::CountInCollection() {
  if (InSequence()) ++collection_sizes_[open_collections_.back()];
}

void SizingPass::Value(std::size_t bytes, const std::string& anchor) {
  CountInCollection();
  Charge(bytes);
  if (!anchor.empty()) Anchor(anchor, bytes);
}

void SizingPass::Anchor(const std::string& anchor, std::size_t bytes) {
  Charge(bytes + kMapMemberBytes + anchor.size());
  anchored_bytes_[anchor] = bytes;
}

}  // namespace rigid_body_sim::yaml_passes
