#include "rigid_body_sim/ros/yaml_value.h"

#include <cctype>
#include <cstdlib>
#include <map>
#include <streambuf>
#include <vector>

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include "rigid_body_sim/ros/scene_params.h"

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;

// What a value costs once built, as glibc allocates for XmlRpcValue: the
// 16-byte value itself in its parent, plus what it owns on the heap.
constexpr std::size_t kSlotBytes = sizeof(XmlRpcValue);
constexpr std::size_t kStringBytes = 64;       // a new'd std::string, its buffer's header
constexpr std::size_t kSequenceBytes = 64;     // a new'd std::vector, its buffer's header
constexpr std::size_t kMapBytes = 64;          // a new'd std::map
constexpr std::size_t kMapMemberBytes = 80;    // a tree node with its key string

std::string MiB(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// A read-only stream over the text, so that neither pass copies it.
class TextBuffer : public std::streambuf {
 public:
  explicit TextBuffer(const std::string& text) {
    char* begin = const_cast<char*>(text.data());  // never written: no put area
    setg(begin, begin, begin + text.size());
  }
};

// Whether a plain scalar certainly becomes a number (so owns no string):
// digits with a sign, a point and an exponent of at most two digits, short
// enough that the conversion can neither overflow nor lose the digits.
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
    for (; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i) ++exponent_digits;
    if (exponent_digits == 0 || exponent_digits > 2) return false;
  }
  return i == text.size();
}

std::size_t ScalarBytes(const std::string& tag, const std::string& text) {
  if (tag != "!" && CertainlyNumber(text)) return kSlotBytes;
  return kSlotBytes + kStringBytes + text.size();  // what a string costs; bools cost less
}

// A plain decimal integer that fits an int, without a leading zero (which
// yaml-cpp reads as octal).
bool PlainInt(const std::string& text) {
  const std::size_t sign = (text[0] == '+' || text[0] == '-') ? 1 : 0;
  const std::size_t digits = text.size() - sign;
  if (digits == 0 || digits > 9 || (digits > 1 && text[sign] == '0')) return false;
  return text.find_first_not_of("0123456789", sign) == std::string::npos;
}

XmlRpcValue FromScalar(const std::string& tag, const std::string& text) {
  if (tag == "!") return XmlRpcValue(text);  // quoted: a string as written
  // The common numbers directly, as yaml-cpp's stream conversions read them.
  if (CertainlyNumber(text)) {
    if (PlainInt(text)) return XmlRpcValue(static_cast<int>(std::strtol(text.c_str(), nullptr, 10)));
    if (text.find_first_of(".eE") != std::string::npos) return XmlRpcValue(std::strtod(text.c_str(), nullptr));
  }
  const YAML::Node node(text);
  int integer = 0;
  if (YAML::convert<int>::decode(node, integer)) return XmlRpcValue(integer);
  double number = 0.0;
  if (YAML::convert<double>::decode(node, number)) return XmlRpcValue(number);
  bool flag = false;
  if (YAML::convert<bool>::decode(node, flag)) return XmlRpcValue(flag);
  return XmlRpcValue(text);
}

// Both passes see the same events; this base keeps what they share: the
// nesting, whether the next event of a map is a key, and the refusals.
class BoundedHandler : public YAML::EventHandler {
 protected:
  struct Open {
    bool is_map;
    bool expects_key;  // maps alternate key, value
  };

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}

  // Called before each node: whether it is a map key.
  bool TakesKey() {
    if (open_.empty() || !open_.back().is_map) return false;
    const bool key = open_.back().expects_key;
    open_.back().expects_key = !key;
    return key;
  }
  void Push(bool is_map) {
    if (static_cast<int>(open_.size()) >= kMaxYamlDepth) {
      throw SceneError("YAML nested deeper than " + std::to_string(kMaxYamlDepth) +
                       " (the limit for a service text)");
    }
    open_.push_back({is_map, true});
  }
  std::vector<Open> open_;
};

// First pass: the expanded memory of the values, and the size of every
// sequence in event order, with nothing allocated per value.
class SizingPass : public BoundedHandler {
 public:
  const std::vector<std::size_t>& sequence_sizes() const { return sequence_sizes_; }
  // Whether a map key was not a plain scalar: refused once the text has
  // parsed, since an unclosed bracket looks like one until the parser sees
  // the end.
  bool has_complex_key() const { return has_complex_key_; }

  void OnNull(const YAML::Mark&, YAML::anchor_t anchor) override {
    if (TakesKey()) has_complex_key_ = true;  // a null key is no name either
    Value(kSlotBytes, anchor);
  }
  void OnAlias(const YAML::Mark&, YAML::anchor_t anchor) override {
    if (TakesKey()) has_complex_key_ = true;
    const auto anchored = anchored_bytes_.find(anchor);
    Value(anchored == anchored_bytes_.end() ? kSlotBytes : anchored->second, YAML::NullAnchor);
  }
  void OnScalar(const YAML::Mark&, const std::string& tag, YAML::anchor_t anchor,
                const std::string& value) override {
    if (TakesKey()) {
      Charge(kMapMemberBytes + value.size());
      return;
    }
    Value(ScalarBytes(tag, value), anchor);
  }
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    Start(false, kSlotBytes + kSequenceBytes, anchor);
    sequences_.push_back(sequence_sizes_.size());
    sequence_sizes_.push_back(0);
  }
  void OnSequenceEnd() override {
    sequences_.pop_back();
    End();
  }
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    Start(true, kSlotBytes + kMapBytes, anchor);
  }
  void OnMapEnd() override { End(); }

 private:
  struct Started {
    std::size_t bytes_before;
    YAML::anchor_t anchor;
  };

  void Charge(std::size_t bytes) {
    if (bytes > kMaxYamlValueBytes - total_bytes_) {
      throw SceneError("the YAML text expands to more than " + MiB(kMaxYamlValueBytes) +
                       " of values, aliases counted at every use (the limit for a service text)");
    }
    total_bytes_ += bytes;
  }
  void CountInSequence() {
    if (!open_.empty() && !open_.back().is_map) ++sequence_sizes_[sequences_.back()];
  }
  // A value complete in one event; an anchored one is kept as a copy too.
  void Value(std::size_t bytes, YAML::anchor_t anchor) {
    CountInSequence();
    Charge(bytes);
    if (anchor != YAML::NullAnchor) Anchor(anchor, bytes);
  }
  void Anchor(YAML::anchor_t anchor, std::size_t bytes) {
    Charge(bytes);
    anchored_bytes_[anchor] = bytes;
  }
  void Start(bool is_map, std::size_t bytes, YAML::anchor_t anchor) {
    if (TakesKey()) has_complex_key_ = true;
    CountInSequence();
    started_.push_back({total_bytes_, anchor});
    Push(is_map);
    Charge(bytes);
  }
  void End() {
    open_.pop_back();
    const Started started = started_.back();
    started_.pop_back();
    if (started.anchor != YAML::NullAnchor) Anchor(started.anchor, total_bytes_ - started.bytes_before);
  }

  std::size_t total_bytes_ = 0;
  bool has_complex_key_ = false;
  std::vector<Started> started_;
  std::vector<std::size_t> sequences_;       // open sequences' indices into sequence_sizes_
  std::vector<std::size_t> sequence_sizes_;  // every sequence's size, in event order
  std::map<YAML::anchor_t, std::size_t> anchored_bytes_;
};

// Second pass: the values, each built in its place (XmlRpcValue copies
// deeply, so nothing is built first and copied in, but for aliases).
class BuildingPass : public BoundedHandler {
 public:
  // Builds into *root, which the caller returns without a copy.
  BuildingPass(const std::vector<std::size_t>& sequence_sizes, XmlRpcValue* root)
      : sequence_sizes_(sequence_sizes), root_(*root) {}

  void OnNull(const YAML::Mark&, YAML::anchor_t anchor) override {
    TakesKey();
    Place(XmlRpcValue(), anchor);
  }
  void OnAlias(const YAML::Mark&, YAML::anchor_t anchor) override {
    TakesKey();
    const auto anchored = anchored_.find(anchor);
    Place(anchored == anchored_.end() ? XmlRpcValue() : anchored->second, YAML::NullAnchor);
  }
  void OnScalar(const YAML::Mark&, const std::string& tag, YAML::anchor_t anchor,
                const std::string& value) override {
    if (TakesKey()) {
      key_ = value;
      return;
    }
    Place(FromScalar(tag, value), anchor);
  }
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    TakesKey();
    XmlRpcValue& sequence = Slot();
    sequence = XmlRpcValue();
    sequence.setSize(static_cast<int>(sequence_sizes_[next_sequence_++]));
    Enter(sequence, false, anchor);
  }
  void OnSequenceEnd() override { Leave(); }
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    TakesKey();
    XmlRpcValue& map = Slot();
    map = XmlRpcValue();
    map.begin();  // an empty struct, not an invalid value
    Enter(map, true, anchor);
  }
  void OnMapEnd() override { Leave(); }

 private:
  struct Building {
    XmlRpcValue* value;
    int next_index;  // of a sequence
    YAML::anchor_t anchor;
  };

  // Where the next value goes: the root, a sequence's next element or the
  // map member named by the last key (a repeated key replaces the value).
  XmlRpcValue& Slot() {
    if (building_.empty()) return root_;
    Building& parent = building_.back();
    if (open_.back().is_map) return (*parent.value)[key_];
    return (*parent.value)[parent.next_index++];
  }
  void Place(const XmlRpcValue& value, YAML::anchor_t anchor) {
    XmlRpcValue& slot = Slot();
    slot = value;
    if (anchor != YAML::NullAnchor) anchored_[anchor] = slot;
  }
  void Enter(XmlRpcValue& value, bool is_map, YAML::anchor_t anchor) {
    building_.push_back({&value, 0, anchor});
    Push(is_map);
  }
  void Leave() {
    open_.pop_back();
    const Building done = building_.back();
    building_.pop_back();
    if (done.anchor != YAML::NullAnchor) anchored_[done.anchor] = *done.value;
  }

  const std::vector<std::size_t>& sequence_sizes_;
  std::size_t next_sequence_ = 0;
  XmlRpcValue& root_;
  std::vector<Building> building_;
  std::string key_;
  std::map<YAML::anchor_t, XmlRpcValue> anchored_;
};

void ParseFirstDocument(const std::string& text, YAML::EventHandler* handler) {
  TextBuffer buffer(text);
  std::istream stream(&buffer);
  YAML::Parser parser(stream);
  parser.HandleNextDocument(*handler);
}

}  // namespace

XmlRpcValue XmlRpcFromYaml(const std::string& text) {
  if (text.size() > kMaxYamlTextBytes) {
    throw SceneError("the YAML text has " + std::to_string(text.size()) + " bytes, more than " +
                     MiB(kMaxYamlTextBytes) + " (the limit for a service text)");
  }
  XmlRpcValue root;
  try {
    SizingPass sizing;
    ParseFirstDocument(text, &sizing);
    if (sizing.has_complex_key()) {
      throw SceneError("YAML map keys must be plain scalars (not sequences, maps or aliases)");
    }
    BuildingPass building(sizing.sequence_sizes(), &root);
    ParseFirstDocument(text, &building);
  } catch (const YAML::Exception& error) {
    throw SceneError(std::string("not valid YAML: ") + error.what());
  }
  return root;
}

}  // namespace rigid_body_sim
