// The manual's programming interface (§10.4.11) through the legacy headers:
// the inferential cycle exactly as the manual writes it, with the user's
// own Parser and Messenger classes, on the harvesting example (whose
// README works the commands by hand). The manual's `crisp-data` (in
// `destroy_object<crisp-data>` and `crisp-data *c`) is a typo for
// crisp_data: a hyphen cannot be part of a C++ name.
#include <brian.h>
#include <interf_obj.h>

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace fs = std::filesystem;

// The user's classes, as the manual describes them.
class Parser {
 public:
  // Auto, target visible 200 cm ahead, battery 100 %, obstacle 500 cm
  // (the harvesting README's first worked cycle).
  crisp_data_list* get_data() {
    crisp_data_list* cdl = new crisp_data_list();
    cdl->add(new crisp_data("Status", 1, 1));
    cdl->add(new crisp_data("TargetVisible", 1, 1));
    cdl->add(new crisp_data("TargetDistance", 200, 1));
    cdl->add(new crisp_data("TargetAngle", 0, 1));
    cdl->add(new crisp_data("Battery", 100, 1));
    cdl->add(new crisp_data("Grasping", 0, 1));
    cdl->add(new crisp_data("ObstacleDistance", 500, 1));
    cdl->add(new crisp_data("ObstacleAngle", 0, 1));
    cdl->add(new crisp_data("HomeDistance", 300, 1));
    cdl->add(new crisp_data("HomeAngle", 180, 1));
    return cdl;
  }
};

class Messenger {
 public:
  void send_data(command_list* com) {
    for (command* c : *com) sent[c->get_name()] = c->get_set_point();
  }
  std::map<std::string, double> sent;
};

namespace {
// Runs `body` with the rule base's directory as working directory (the
// manual passes bare file names).
template <class F>
void in_directory(const fs::path& dir, F body) {
  const fs::path old = fs::current_path();
  fs::current_path(dir);
  body();
  fs::current_path(old);
}
}  // namespace

// The README's numbers: GoToTarget proposes FAST (TargetFar 1) and NORTH
// (TargetNorth 1) with WANT 1; GoToHome (WANT 0) contributes nothing ->
// SpeedModule 75, SpeedAngle 0; no Grasp.
TEST(LegacyApi, ManualInferentialCycle) {
  in_directory(MRT_BRIAN_EXAMPLES_DIR "/harvesting", [] {
    Brian* brian_the_brain = new Brian("ctof.txt", "shape_ctof.txt", "Predicate.ini", "PredicateActions.ini",
                                       "Cando.ini", "behavior.txt", "want.txt", "s_ftoc.txt", "s_shape.txt");
    //definitions
    crisp_data_list *cl;
    command_list *com;
    Parser *p = new Parser();
    Messenger *m = new Messenger();

    //main cycle
    cl = p->get_data();
    com = brian_the_brain->run(cl);
    m->send_data(com);

    EXPECT_NEAR(m->sent["SpeedModule"], 75.0, 1e-9);
    EXPECT_NEAR(m->sent["SpeedAngle"], 0.0, 1e-9);
    EXPECT_EQ(m->sent.count("Grasp"), 0u);
    command *c = com->get_command("SpeedModule");
    ASSERT_NE(c, nullptr);
    EXPECT_NEAR(c->get_set_point(), 75.0, 1e-9);
    EXPECT_EQ(com->get_command("Engine"), nullptr);

    for_each(cl->begin(), cl->end(), destroy_object<crisp_data>());
    delete cl;
    for_each(com->begin(), com->end(), destroy_object<command>());
    delete com;
    delete m;
    delete p;
    delete brian_the_brain;
  });
}

// The list objects of §10.4.11, word for word (but crisp_data for crisp-data).
TEST(LegacyApi, ListsAsTheManualUsesThem) {
  crisp_data_list* cdl = new crisp_data_list();
  cdl->add(new crisp_data("TargetDistance", 35.56, 0.8));
  crisp_data *c = cdl->get_by_name("TargetDistance");
  ASSERT_NE(c, nullptr);
  EXPECT_STREQ(c->get_name(), "TargetDistance");
  EXPECT_DOUBLE_EQ(c->get_value(), 35.56);
  EXPECT_DOUBLE_EQ(c->get_reliability(), 0.8);
  EXPECT_EQ(cdl->get_by_name("Nothing"), nullptr);
  for_each(cdl->begin(), cdl->end(), destroy_object<crisp_data>());
  delete cdl;

  command_list *com = new command_list();
  com->add(new command("Engine",68.56));
  command *e = com->get_command("Engine");
  ASSERT_NE(e, nullptr);
  EXPECT_DOUBLE_EQ(e->get_set_point(), 68.56);
  for_each(com->begin(), com->end(), destroy_object<command>());
  delete com;
}

// The manual's eight-file constructor (no predicate actions), on a small
// base: Obstacle 80 on DIST (TOL NEAR 0 100, TOR FAR 0 100) -> NEAR 0.2,
// FAR 0.8; Cruise (CANDO FAR 0.8, WANT 1 - NEAR = 0.8) proposes FAST 0.8
// and SLOW 0.2, weighted 0.64 and 0.16 -> (30*0.64 + 10*0.16) / 0.8 = 26.
// The user's Parser/Messenger may also implement the project's interfaces.
TEST(LegacyApi, EightFileConstructorAndInterfaces) {
  const fs::path d = fs::temp_directory_path() / ("brian_legacy_api_" + std::to_string(::getpid()));
  fs::create_directories(d);
  auto write = [&](const char* name, const char* text) { std::ofstream(d / name) << text; };
  write("shape_ctof.txt", "(DIST (TOL (NEAR 0 100)) (TOR (FAR 0 100)))\n");
  write("ctof.txt", "(Obstacle DIST)\n");
  write("Predicate.ini", "Near = (D Obstacle NEAR);\nFar = (D Obstacle FAR);\n");
  write("Cando.ini", "Cruise = (P Far);\n");
  write("want.txt", "Cruise = (NOT (P Near));\n");
  write("behavior.txt", "(level 1 Cruise cruise.rul)\n");
  write("cruise.rul", "(Far) => (Speed FAST);\n(Near) => (Speed SLOW);\n");
  write("s_shape.txt", "(SPD (SNG (STOP 0)) (SNG (SLOW 10)) (SNG (FAST 30)))\n");
  write("s_ftoc.txt", "(Speed SPD)\n");
  struct Source : mrt::brian::legacy::DataSource {
    crisp_data_list* get_data() override {
      auto* l = new crisp_data_list();
      l->add(new crisp_data("Obstacle", 80, 1));
      return l;
    }
  };
  struct Sink : mrt::brian::legacy::CommandSink {
    void send_data(command_list* com) override { speed = com->get_command("Speed")->get_set_point(); }
    double speed = -1;
  };
  in_directory(d, [] {
    Brian brian("ctof.txt", "shape_ctof.txt", "Predicate.ini", "Cando.ini", "behavior.txt", "want.txt", "s_ftoc.txt",
                "s_shape.txt");
    Source source;
    Sink sink;
    crisp_data_list* cl = source.get_data();
    command_list* com = brian.run(cl);
    sink.send_data(com);
    EXPECT_NEAR(sink.speed, 26.0, 1e-9);
    for_each(cl->begin(), cl->end(), destroy_object<crisp_data>());
    delete cl;
    for_each(com->begin(), com->end(), destroy_object<command>());
    delete com;
  });
  fs::remove_all(d);
}
