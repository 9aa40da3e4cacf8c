// fem::UnsupportedNotes: the one add-or-count of Model::unsupported by name (model.hpp).
#include "seflex/fem/model.hpp"

namespace seflex::fem {

UnsupportedNotes::UnsupportedNotes(std::vector<UnsupportedCard>& list) : list_(&list) {
  index_.reserve(list.size());
  for (std::size_t i = 0; i < list.size(); ++i) index_.try_emplace(list[i].name, i);  // the first of a name, as a search finds
}

UnsupportedCard& UnsupportedNotes::add(const std::string& name, const CardRef& first, std::size_t count) {
  const auto [it, inserted] = index_.try_emplace(name, list_->size());
  if (inserted) list_->push_back({name, 0, first, {}});
  UnsupportedCard& u = (*list_)[it->second];
  u.count += count;
  return u;
}

UnsupportedCard* UnsupportedNotes::find(const std::string& name) {
  const auto it = index_.find(name);
  return it == index_.end() ? nullptr : &(*list_)[it->second];
}

}  // namespace seflex::fem
