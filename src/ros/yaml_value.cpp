// ~spawn_body's YAML text to XmlRpc values: libyaml's parser, the second pass
// (the values) and the two passes together; the first is in yaml_sizing.cpp.
#include "rigid_body_sim/ros/yaml_value.h"

#include <cstdlib>
#include <map>
#include <new>
#include <vector>

#include <yaml-cpp/yaml.h>
#include <yaml.h>

#include "rigid_body_sim/ros/scene_params.h"
#include "yaml_passes.h"

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;
using yaml_passes::CertainlyNumber;
using yaml_passes::Event;
using yaml_passes::EventPass;
using yaml_passes::IsNull;
using yaml_passes::MiB;
using yaml_passes::SizingPass;

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
