#include "mrt_brian/legacy.h"

#include <cstring>

namespace mrt::brian::legacy {

crisp_data* crisp_data_list::get_by_name(const char* name) const {
  for (crisp_data* d : *this)
    if (d && std::strcmp(d->get_name(), name) == 0) return d;
  return nullptr;
}

command* command_list::get_command(const char* name) const {
  for (command* c : *this)
    if (c && std::strcmp(c->get_name(), name) == 0) return c;
  return nullptr;
}

Brian::Brian(const char* fuzzyassoc, const char* fuzzyshapes, const char* pries, const char* candoes,
             const char* behaviors, const char* wanters, const char* defuzzyassoc, const char* defuzzyshapes,
             const BrianOptions& options)
    : impl_(std::make_unique<mrt::brian::Brian>(fuzzyassoc, fuzzyshapes, pries, "", candoes, behaviors, wanters,
                                                defuzzyassoc, defuzzyshapes, options)) {}

Brian::Brian(const char* fuzzyassoc, const char* fuzzyshapes, const char* pries, const char* predicate_actions,
             const char* candoes, const char* behaviors, const char* wanters, const char* defuzzyassoc,
             const char* defuzzyshapes, const BrianOptions& options)
    : impl_(std::make_unique<mrt::brian::Brian>(fuzzyassoc, fuzzyshapes, pries, predicate_actions, candoes,
                                                behaviors, wanters, defuzzyassoc, defuzzyshapes, options)) {}

command_list* Brian::run(crisp_data_list* data) {
  input_.clear();
  if (data)
    for (const crisp_data* d : *data)
      if (d) input_.push_back({d->get_name(), d->get_value(), d->get_reliability()});
  auto* out = new command_list();
  for (const Command& c : impl_->run(input_)) out->add(new command(c.name.c_str(), c.value));
  return out;
}

}  // namespace mrt::brian::legacy
