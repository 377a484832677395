#include "rigid_body_sim/ros/yaml_value.h"

#include <cctype>
#include <cstdlib>
#include <map>
#include <new>
#include <vector>

#include <yaml-cpp/yaml.h>
#include <yaml.h>

#include "rigid_body_sim/ros/scene_params.h"

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;

// What a value costs once built, as glibc allocates for XmlRpcValue: the
// 16-byte value itself in its parent, plus what it owns on the heap.
constexpr std::size_t kSlotBytes = sizeof(XmlRpcValue);
constexpr std::size_t kStringBytes = 64;      // a new'd std::string, its buffer's header
constexpr std::size_t kCollectionBytes = 64;  // a new'd std::vector or std::map
constexpr std::size_t kMapMemberBytes = 80;   // a tree node with its key string

std::string MiB(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

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
    for (; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i)
      ++exponent_digits;
    if (exponent_digits == 0 || exponent_digits > 2) return false;
  }
  return i == text.size();
}

// A plain decimal integer that fits an int, without a leading zero (which
// yaml-cpp reads as octal).
bool PlainInt(const std::string& text) {
  const std::size_t sign = (text[0] == '+' || text[0] == '-') ? 1 : 0;
  const std::size_t digits = text.size() - sign;
  if (digits == 0 || digits > 9 || (digits > 1 && text[sign] == '0')) return false;
  return text.find_first_not_of("0123456789", sign) == std::string::npos;
}

// A plain scalar as rosparam reads it.
XmlRpcValue FromPlainScalar(const std::string& text) {
  // The common numbers directly, as yaml-cpp's stream conversions read them.
  if (CertainlyNumber(text)) {
    if (PlainInt(text))
      return XmlRpcValue(static_cast<int>(std::strtol(text.c_str(), nullptr, 10)));
    if (text.find_first_of(".eE") != std::string::npos)
      return XmlRpcValue(std::strtod(text.c_str(), nullptr));
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

// A null as YAML 1.1 writes it (yaml-cpp reads the same plain scalars).
bool IsNull(const std::string& text) {
  return text.empty() || text == "~" || text == "null" || text == "Null" || text == "NULL";
}

// One parsed event, as both passes see it.
struct Event {
  yaml_event_type_t type = YAML_NO_EVENT;
  std::string anchor;  // empty: none; of an alias, the anchor it names
  bool plain = false;  // a plain (unquoted) scalar
  std::string value;
};

// Both passes see the same events; this base keeps what they share: the
// nesting, whether the next event of a map is a key, and the refusals.
class EventPass {
 public:
  virtual ~EventPass() = default;

  void Take(const Event& event) {
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
  // Whether a map key was not a plain scalar: refused once the whole text
  // has parsed, so that a malformed text is reported as such.
  bool has_complex_key() const { return has_complex_key_; }

 protected:
  virtual void Key(const std::string& key) = 0;
  virtual void Scalar(const Event& event) = 0;
  virtual void Alias(const std::string& anchor) = 0;
  virtual void Start(bool is_map, const std::string& anchor) = 0;
  virtual void End() = 0;

  bool InSequence() const { return !open_.empty() && !open_.back().is_map; }

 private:
  struct Open {
    bool is_map;
    bool expects_key;  // maps alternate key, value
  };

  bool TakesKey() {
    if (open_.empty() || !open_.back().is_map) return false;
    const bool key = open_.back().expects_key;
    open_.back().expects_key = !key;
    return key;
  }

  std::vector<Open> open_;
  bool has_complex_key_ = false;
};

// First pass: the expanded memory of the values, and the size of every
// collection in event order, with nothing allocated per value.
class SizingPass : public EventPass {
 public:
  const std::vector<std::size_t>& collection_sizes() const { return collection_sizes_; }

 private:
  struct Started {
    std::size_t bytes_before;
    std::string anchor;
  };

  void Key(const std::string& key) override { Charge(kMapMemberBytes + key.size()); }
  void Scalar(const Event& event) override {
    const bool owns_nothing = event.plain && (CertainlyNumber(event.value) || IsNull(event.value));
    Value(owns_nothing ? kSlotBytes : kSlotBytes + kStringBytes + event.value.size(), event.anchor);
  }
  void Alias(const std::string& anchor) override {
    const auto anchored = anchored_bytes_.find(anchor);
    if (anchored == anchored_bytes_.end()) {
      throw SceneError("not valid YAML: the alias *" + anchor.substr(0, 64) +
                       " names no anchor before it");
    }
    Value(anchored->second, "");
  }
  void Start(bool /*is_map*/, const std::string& anchor) override {
    CountInCollection();
    started_.push_back({total_bytes_, anchor});
    Charge(kSlotBytes + kCollectionBytes);
    open_collections_.push_back(collection_sizes_.size());
    collection_sizes_.push_back(0);
  }
  void End() override {
    open_collections_.pop_back();
    const Started started = started_.back();
    started_.pop_back();
    if (!started.anchor.empty()) Anchor(started.anchor, total_bytes_ - started.bytes_before);
  }

  void Charge(std::size_t bytes) {
    if (bytes > kMaxYamlValueBytes - total_bytes_) {
      throw SceneError("the YAML text expands to more than " + MiB(kMaxYamlValueBytes) +
                       " of values, aliases counted at every use (the limit for a service text)");
    }
    total_bytes_ += bytes;
  }
  void CountInCollection() {
    if (InSequence()) ++collection_sizes_[open_collections_.back()];
  }
  // A value complete in one event.
  void Value(std::size_t bytes, const std::string& anchor) {
    CountInCollection();
    Charge(bytes);
    if (!anchor.empty()) Anchor(anchor, bytes);
  }
  // An anchored value is kept as a copy for its aliases.
  void Anchor(const std::string& anchor, std::size_t bytes) {
    Charge(bytes + kMapMemberBytes + anchor.size());
    anchored_bytes_[anchor] = bytes;
  }

  std::size_t total_bytes_ = 0;
  std::vector<Started> started_;
  std::vector<std::size_t> open_collections_;  // indices into collection_sizes_
  std::vector<std::size_t> collection_sizes_;  // every collection's size, in event order
  std::map<std::string, std::size_t> anchored_bytes_;
};

// Second pass: the values, each built in its place (XmlRpcValue copies
// deeply, so nothing is built first and copied in, but for aliases).
class BuildingPass : public EventPass {
 public:
  // Builds into *root, which the caller returns without a copy.
  BuildingPass(const std::vector<std::size_t>& collection_sizes, XmlRpcValue* root)
      : collection_sizes_(collection_sizes), root_(*root) {}

 private:
  struct Building {
    XmlRpcValue* value;
    int next_index;  // of a sequence
    std::string anchor;
  };

  void Key(const std::string& key) override { key_ = key; }
  void Scalar(const Event& event) override {
    if (!event.plain) {
      Place(XmlRpcValue(event.value), event.anchor);  // quoted: a string as written
    } else if (IsNull(event.value)) {
      Place(XmlRpcValue(), event.anchor);
    } else {
      Place(FromPlainScalar(event.value), event.anchor);
    }
  }
  void Alias(const std::string& anchor) override { Place(anchored_.at(anchor), ""); }
  void Start(bool is_map, const std::string& anchor) override {
    XmlRpcValue& value = Slot();
    value = XmlRpcValue();
    const std::size_t size = collection_sizes_[next_collection_++];
    if (is_map) {
      value.begin();  // an empty struct, not an invalid value
    } else {
      value.setSize(static_cast<int>(size));
    }
    building_.push_back({&value, 0, anchor});
  }
  void End() override {
    const Building done = building_.back();
    building_.pop_back();
    if (!done.anchor.empty()) anchored_[done.anchor] = *done.value;
  }

  // Where the next value goes: the root, a sequence's next element or the
  // map member named by the last key (a repeated key replaces the value).
  XmlRpcValue& Slot() {
    if (building_.empty()) return root_;
    Building& parent = building_.back();
    if (!InSequence()) return (*parent.value)[key_];
    return (*parent.value)[parent.next_index++];
  }
  void Place(const XmlRpcValue& value, const std::string& anchor) {
    XmlRpcValue& slot = Slot();
    slot = value;
    if (!anchor.empty()) anchored_[anchor] = slot;
  }

  const std::vector<std::size_t>& collection_sizes_;
  std::size_t next_collection_ = 0;
  XmlRpcValue& root_;
  std::vector<Building> building_;
  std::string key_;
  std::map<std::string, XmlRpcValue> anchored_;
};

// libyaml's event parser: its lookahead is bounded (a simple key spans at
// most 1,024 characters), so a long one-line flow sequence is read in
// constant memory, where yaml-cpp's scanner holds all of its tokens.
class Parser {
 public:
  explicit Parser(const std::string& text) {
    if (!yaml_parser_initialize(&parser_)) throw std::bad_alloc();
    yaml_parser_set_input_string(&parser_, reinterpret_cast<const unsigned char*>(text.data()),
                                 text.size());
  }
  ~Parser() { yaml_parser_delete(&parser_); }
  Parser(const Parser&) = delete;
  Parser& operator=(const Parser&) = delete;

  // Feeds the first document's events to `pass`.
  void Run(EventPass* pass) {
    Event event;
    do {
      Next(&event);
      pass->Take(event);
    } while (event.type != YAML_DOCUMENT_END_EVENT && event.type != YAML_STREAM_END_EVENT);
  }

 private:
  void Next(Event* out) {
    yaml_event_t event;
    if (!yaml_parser_parse(&parser_, &event)) {
      throw SceneError(std::string("not valid YAML: ") +
                       (parser_.problem != nullptr ? parser_.problem : "unreadable") + " at line " +
                       std::to_string(parser_.problem_mark.line + 1) + ", column " +
                       std::to_string(parser_.problem_mark.column + 1));
    }
    const auto text = [](const yaml_char_t* chars) {
      return chars != nullptr ? std::string(reinterpret_cast<const char*>(chars)) : std::string();
    };
    out->type = event.type;
    out->plain = false;
    out->value.clear();
    switch (event.type) {
      case YAML_SCALAR_EVENT:
        out->anchor = text(event.data.scalar.anchor);
        out->value.assign(reinterpret_cast<const char*>(event.data.scalar.value),
                          event.data.scalar.length);
        out->plain = event.data.scalar.style == YAML_PLAIN_SCALAR_STYLE;
        break;
      case YAML_ALIAS_EVENT:
        out->anchor = text(event.data.alias.anchor);
        break;
      case YAML_SEQUENCE_START_EVENT:
        out->anchor = text(event.data.sequence_start.anchor);
        break;
      case YAML_MAPPING_START_EVENT:
        out->anchor = text(event.data.mapping_start.anchor);
        break;
      default:
        out->anchor.clear();
        break;
    }
    yaml_event_delete(&event);
  }

  yaml_parser_t parser_;
};

}  // namespace

XmlRpcValue XmlRpcFromYaml(const std::string& text) {
  if (text.size() > kMaxYamlTextBytes) {
    throw SceneError("the YAML text has " + std::to_string(text.size()) + " bytes, more than " +
                     MiB(kMaxYamlTextBytes) + " (the limit for a service text)");
  }
  SizingPass sizing;
  Parser(text).Run(&sizing);
  if (sizing.has_complex_key()) {
    throw SceneError("YAML map keys must be plain scalars (not sequences, maps or aliases)");
  }
  XmlRpcValue root;
  BuildingPass building(sizing.collection_sizes(), &root);
  Parser(text).Run(&building);
  return root;
}

}  // namespace rigid_body_sim
