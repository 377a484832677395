// A body's name inside the program: a slot and the generation of that slot.
// Removing a body frees its slot for a later one under the next generation,
// so an id held across a removal is caught as stale instead of silently
// naming the body that took the slot.
#pragma once

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigid_body_sim::core {

struct BodyId {
  static constexpr std::uint32_t kNoSlot = std::numeric_limits<std::uint32_t>::max();
  std::uint32_t slot = kNoSlot;
  std::uint32_t generation = 0;

  friend bool operator==(BodyId a, BodyId b) {
    return a.slot == b.slot && a.generation == b.generation;
  }
  friend bool operator!=(BodyId a, BodyId b) { return !(a == b); }
};

// "body id 3.1 is stale": the one message for an id whose body is gone.
std::string StaleIdMessage(BodyId id);

// Per-body data of a table outside the BodyStore, keyed by BodyId: a vector
// indexed by slot, which holds each entry's generation. Nothing moves when a
// body goes, so no table renumbers anything; slots are reused, so the size
// follows the most bodies ever alive at once.
template <typename T>
class BodyMap {
 public:
  // Holds `value` for `id`, replacing whatever the slot held.
  T& Insert(BodyId id, T value) {
    if (id.slot >= entries_.size()) entries_.resize(static_cast<std::size_t>(id.slot) + 1);
    Entry& entry = entries_[id.slot];
    entry.generation = id.generation;
    entry.live = true;
    entry.value = std::move(value);
    return entry.value;
  }
  // Drops `id`'s entry (the slot keeps its memory for the next body).
  void Erase(BodyId id) {
    if (Entry* entry = Find(id)) {
      entry->live = false;
      entry->value = T{};
    }
  }
  bool Contains(BodyId id) const { return Find(id) != nullptr; }
  // Throws std::out_of_range for an id without an entry.
  T& at(BodyId id) { return Checked(Find(id), id)->value; }
  const T& at(BodyId id) const { return Checked(Find(id), id)->value; }
  // Every live entry's value (e.g. to clear them all).
  template <typename F>
  void ForEach(F&& f) {
    for (Entry& entry : entries_) {
      if (entry.live) f(entry.value);
    }
  }

 private:
  struct Entry {
    std::uint32_t generation = 0;
    bool live = false;
    T value{};
  };
  Entry* Find(BodyId id) { return const_cast<Entry*>(static_cast<const BodyMap*>(this)->Find(id)); }
  const Entry* Find(BodyId id) const {
    if (id.slot >= entries_.size()) return nullptr;
    const Entry& entry = entries_[id.slot];
    return entry.live && entry.generation == id.generation ? &entry : nullptr;
  }
  template <typename E>
  static E* Checked(E* entry, BodyId id) {
    if (entry == nullptr) throw std::out_of_range(StaleIdMessage(id));
    return entry;
  }

  std::vector<Entry> entries_;
};

}  // namespace rigid_body_sim::core
