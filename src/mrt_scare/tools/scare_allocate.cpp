// scare_allocate: SCARE's decision and coordination steps on files — prints
// the agenda and the allocation of a situation.
//   scare_allocate --activities config/robocup_activities.yaml --situation s.yaml [--method exact]
#include <cstdio>
#include <iostream>

#include "mrt_common/cli.h"
#include "mrt_common/parse_error.h"
#include "mrt_scare/situation.h"

int main(int argc, char** argv) {
  using namespace mrt::scare;
  CLI::App app{"SCARE coordination: prints the agenda and the allocation of a situation", "scare_allocate"};
  std::string activities, situation, method = "auto";
  app.add_option("--activities", activities, "activity YAML file (jobs, schemata, robots)")->required();
  app.add_option("--situation", situation, "situation YAML file (world crisp data, robots' poses)")->required();
  app.add_option("--method", method, "auto, exact, greedy or local (greedy + local search)")
      ->check(CLI::IsMember({"auto", "exact", "greedy", "local"}));
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  try {
    const ActivitySet set = load_activities(activities);
    const Situation s = load_situation(situation, set);
    const Allocator al(set);
    const Allocator::Method m = method == "exact"    ? Allocator::Method::kExact
                                : method == "greedy" ? Allocator::Method::kGreedy
                                : method == "local"  ? Allocator::Method::kGreedyLocal
                                                     : Allocator::Method::kAuto;
    const Allocation a = al.allocate(team_input(set, s), m);
    std::printf("agenda:\n");
    int rank = 0;
    for (const AgendaEntry& e : a.agenda)
      std::printf("  %2d. %-22s layer %d  opportunity %.3f  priority %.2f  fit %.3f  score %.4f\n", ++rank,
                  set.activities[static_cast<std::size_t>(e.activity)].name.c_str(), e.layer, e.opportunity,
                  e.priority, e.fit, e.score);
    std::printf("allocation (%s, utility %.4f):\n", method.c_str(), a.utility);
    const auto slots = set.slots();
    for (std::size_t i = 0; i < a.robots.size(); ++i)
      std::printf("  %-10s %s\n", a.robots[i].c_str(),
                  a.slot[i] >= 0 ? set.slot_name(slots[static_cast<std::size_t>(a.slot[i])]).c_str() : "-");
  } catch (const mrt::common::ParseError& e) {
    std::cerr << "scare_allocate: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
