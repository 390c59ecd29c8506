// The programming interface of manual §10.4.11 (the 2009 engine's names),
// in mrt::brian::legacy; the legacy headers <interf_obj.h> and <brian.h>
// bring these names into the global namespace so that the manual's code
// compiles unchanged. The user's own `Parser` and `Messenger` classes are
// not defined here (the manual has the user write them); `DataSource` and
// `CommandSink` are the abstract interfaces they can implement.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "mrt_brian/brian.h"

namespace mrt::brian::legacy {

/// `<name, value, reliability>` (§10.4.11: `new crisp_data("TargetDistance", 35.56, 0.8)`).
class crisp_data {
 public:
  crisp_data(const char* name, double value, double reliability = 1.0)
      : name_(name), value_(value), reliability_(reliability) {}
  const char* get_name() const { return name_.c_str(); }
  double get_value() const { return value_; }
  double get_reliability() const { return reliability_; }
  void set_value(double v) { value_ = v; }
  void set_reliability(double r) { reliability_ = r; }

 private:
  std::string name_;
  double value_, reliability_;
};

/// A set-point for a symbolic actuator (`new command("Engine", 68.56)`).
class command {
 public:
  command(const char* name, double set_point) : name_(name), set_point_(set_point) {}
  const char* get_name() const { return name_.c_str(); }
  double get_set_point() const { return set_point_; }
  void set_set_point(double v) { set_point_ = v; }

 private:
  std::string name_;
  double set_point_;
};

/// A list of owned pointers, as in the original: the user deletes the
/// elements (`for_each(l->begin(), l->end(), destroy_object<T>())`) and then
/// the list.
template <class T>
class object_list : public std::vector<T*> {
 public:
  void add(T* item) { this->push_back(item); }
};

class crisp_data_list : public object_list<crisp_data> {
 public:
  /// The first datum named `name`, or nullptr.
  crisp_data* get_by_name(const char* name) const;
};

class command_list : public object_list<command> {
 public:
  /// The command for actuator `name`, or nullptr.
  command* get_command(const char* name) const;
};

/// Deletes one element of a list (for std::for_each), as the original's
/// functor; also takes the <name, object> pairs of map-based lists.
template <class T>
struct destroy_object {
  void operator()(T* p) const { delete p; }
  template <class K>
  void operator()(const std::pair<K, T*>& p) const { delete p.second; }
};

/// The manual's Mr. BRIAN object: the eight files of §10.4.11 (or nine,
/// with the predicate-actions file), `run` returns a new command list the
/// caller destroys. Relative behaviour paths resolve from the working
/// directory, as in the original. Throws mrt::common::ParseError.
class Brian {
 public:
  Brian(const char* fuzzyassoc, const char* fuzzyshapes, const char* pries, const char* candoes,
        const char* behaviors, const char* wanters, const char* defuzzyassoc, const char* defuzzyshapes,
        const BrianOptions& options = {});
  Brian(const char* fuzzyassoc, const char* fuzzyshapes, const char* pries, const char* predicate_actions,
        const char* candoes, const char* behaviors, const char* wanters, const char* defuzzyassoc,
        const char* defuzzyshapes, const BrianOptions& options = {});
  /// One perception-action cycle; the list is only read.
  command_list* run(crisp_data_list* data);
  /// The engine underneath (mrt::brian::Brian).
  mrt::brian::Brian& engine() { return *impl_; }

 private:
  std::unique_ptr<mrt::brian::Brian> impl_;
  CrispDataList input_;
};

/// What the manual's `Parser` does: gives the crisp data of a cycle.
class DataSource {
 public:
  virtual ~DataSource() = default;
  virtual crisp_data_list* get_data() = 0;
};

/// What the manual's `Messenger` does: sends the set-points of a cycle.
class CommandSink {
 public:
  virtual ~CommandSink() = default;
  virtual void send_data(command_list* com) = 0;
};

}  // namespace mrt::brian::legacy
