// The passes of XmlRpcFromYaml (yaml_value.cpp) over libyaml's events:
// what both see, and the first, which sizes the values without building
// them (yaml_sizing.cpp). Private to src/ros.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <yaml.h>

namespace rigid_body_sim::yaml_passes {

// "<n> MiB", for the messages that name a limit.
std::string MiB(std::size_t bytes);

// Whether a plain scalar certainly becomes a number (so owns no string):
// digits with a sign, a point and an exponent of at most two digits, short
// enough that the conversion can neither overflow nor lose the digits.
bool CertainlyNumber(const std::string& text);

// A null as YAML 1.1 writes it (yaml-cpp reads the same plain scalars).
bool IsNull(const std::string& text);

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

  void Take(const Event& event);
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

  bool TakesKey();

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

  void Key(const std::string& key) override;
  void Scalar(const Event& event) override;
  void Alias(const std::string& anchor) override;
  void Start(bool is_map, const std::string& anchor) override;
  void End() override;

  void Charge(std::size_t bytes);
  void CountInCollection();
  // A value complete in one event.
  void Value(std::size_t bytes, const std::string& anchor);
  // An anchored value is kept as a copy for its aliases.
  void Anchor(const std::string& anchor, std::size_t bytes);

  std::size_t total_bytes_ = 0;
  std::vector<Started> started_;
  std::vector<std::size_t> open_collections_;  // indices into collection_sizes_
  std::vector<std::size_t> collection_sizes_;  // every collection's size, in event order
  std::map<std::string, std::size_t> anchored_bytes_;
};

}  // namespace rigid_body_sim::yaml_passes
