#include "rigid_body_sim/core/body_store.h"

#include <stdexcept>

namespace rigid_body_sim::core {

std::string StaleIdMessage(BodyId id) {
  return "body id " + std::to_string(id.slot) + "." + std::to_string(id.generation) +
         " names no living body";
}

BodyId BodyStore::Add(BodyDef def) {
  BodyId id;
  if (free_slots_.empty()) {
    id.slot = static_cast<std::uint32_t>(slots_.size());
    slots_.emplace_back();
  } else {
    id.slot = free_slots_.back();
    free_slots_.pop_back();
  }
  Slot& slot = slots_[id.slot];
  id.generation = slot.generation;
  slot.index = size();
  slot.live = true;
  by_name_.emplace(def.model.name(), id);
  for (std::size_t k = 0; k < def.frames.sites.size(); ++k) {
    sites_by_name_.emplace(def.frames.sites[k].name, SiteRef{id, k});
  }

  hot_.models.push_back(std::move(def.model));
  hot_.states.push_back(def.initial_state);
  hot_.loads.emplace_back();
  hot_.loaded.push_back(0);
  hot_.faults.push_back(BodyFault::kNone);
  hot_.one_step_momentum_sq.push_back(0.0);
  cold_.ids.push_back(id);
  cold_.initial_states.push_back(def.initial_state);
  cold_.properties.push_back(def.properties);
  cold_.frames.push_back(std::move(def.frames));
  return id;
}

void BodyStore::Remove(BodyId id) {
  const std::size_t index = CheckedIndex(id);
  by_name_.erase(hot_.models[index].name());
  for (const Site& site : cold_.frames[index].sites) sites_by_name_.erase(site.name);
  // The one place a body's entries are erased: every column, in one pass.
  const auto erase = [index](auto& column) {
    if (index < column.size()) column.erase(column.begin() + static_cast<std::ptrdiff_t>(index));
  };
  hot_.ForEach(erase);
  cold_.ForEach(erase);
  for (std::size_t i = index; i < size(); ++i) slots_[cold_.ids[i].slot].index = i;
  Slot& slot = slots_[id.slot];
  slot.live = false;
  ++slot.generation;  // the old id is stale from now on, before the slot is reused
  free_slots_.push_back(id.slot);
}

std::optional<std::size_t> BodyStore::IndexOf(BodyId id) const {
  if (id.slot >= slots_.size()) return std::nullopt;
  const Slot& slot = slots_[id.slot];
  if (!slot.live || slot.generation != id.generation) return std::nullopt;
  return slot.index;
}

std::size_t BodyStore::CheckedIndex(BodyId id) const {
  const std::optional<std::size_t> index = IndexOf(id);
  if (!index) throw std::out_of_range(StaleIdMessage(id));
  return *index;
}

std::optional<BodyId> BodyStore::Find(const std::string& name) const {
  const auto found = by_name_.find(name);
  if (found == by_name_.end()) return std::nullopt;
  return found->second;
}

std::optional<SiteRef> BodyStore::FindSite(const std::string& name) const {
  const auto found = sites_by_name_.find(name);
  if (found == sites_by_name_.end()) return std::nullopt;
  return found->second;
}

}  // namespace rigid_body_sim::core
