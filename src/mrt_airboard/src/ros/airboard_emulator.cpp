// airboard_emulator: the AIRBoard firmware model on a pseudo-terminal.
// A plain program, runnable as a <node> in a launch file (ROS arguments of
// the form name:=value are ignored); only with --ros-time or --sim-wheel-cmd
// does it join the ROS graph: to take its board time from ros::Time (a
// simulator's /clock when /use_sim_time is true), and to publish the wheel
// speeds the board reports, at every state frame it sends, as the wheel
// commands of a simulated base (mrt_msgs/WheelCommand, MODE_SPEED): the
// emulated board's wheels drive mrt_sim's robot, the driver knows nothing
// of it.
#include <atomic>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <mrt_msgs/WheelCommand.h>
#include <ros/ros.h>

#include "mrt_airboard/pty_emulator.h"

namespace {
std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

void usage() {
  std::cerr <<
      "usage: airboard_emulator [options]\n"
      "  --link PATH           create PATH as a symlink to the pty slave (give it to the node's ~port)\n"
      "  --motors N            motors on the board, 1..4 (default 2)\n"
      "  --cpr N               encoder counts per wheel revolution (default 8192)\n"
      "  --max-speed W         set-point clamp, rad/s (default 30)\n"
      "  --no-load-speed W     wheel speed at 100 % duty, rad/s (default 38)\n"
      "  --tau S               motor time constant, s (default 0.02)\n"
      "  --watchdog-ms MS      watchdog delay (default 100)\n"
      "  --corrupt-rate P      flip one bit in a fraction P of the PC->board bytes\n"
      "  --corrupt-tx-rate P   same for board->PC bytes\n"
      "  --cut-rx-after S      lose every PC->board byte after S s of board time\n"
      "  --seed N              seed of the fault generator (default 1)\n"
      "  --baud N              carry bytes at the rate of an N-baud 8N1 line (default 0: instantly)\n"
      "  --require-checked     refuse plain SET_SPEED / SET_PWM from power-up (CRC-32 checked ones only)\n"
      "  --ros-time            board time follows ros::Time (the simulator's /clock under /use_sim_time)\n"
      "                        instead of the wall clock; needs a ROS master\n"
      "  --sim-wheel-cmd TOPIC publish the wheel speeds of every state frame the board sends as\n"
      "                        mrt_msgs/WheelCommand (MODE_SPEED) on TOPIC (a simulator's\n"
      "                        <robot>/wheel_cmd: the board's wheels drive the simulated base);\n"
      "                        needs a ROS master\n"
      "Prints 'pty: <slave path>' on stdout, serves until SIGINT/SIGTERM, then\n"
      "prints its statistics on stderr. Arguments name:=value (ROS) are ignored.\n";
}
}  // namespace

int main(int argc, char** argv) {
  mrt::airboard::FirmwareConfig fw;
  mrt::airboard::LineFaults faults;
  std::string link, sim_wheel_cmd;
  bool ros_time = false;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      // roslaunch adds __name:=, __log:= and the remappings (from:=to) of
      // the enclosing group: not ours.
      if (a.find(":=") != std::string::npos) continue;
      auto val = [&]() -> std::string {
        if (i + 1 >= argc) throw std::invalid_argument("option " + a + " needs a value");
        return argv[++i];
      };
      if (a == "--link") link = val();
      else if (a == "--motors") fw.motors = std::stoi(val());
      else if (a == "--cpr") fw.counts_per_rev = static_cast<uint32_t>(std::stoul(val()));
      else if (a == "--max-speed") fw.max_speed = std::stod(val());
      else if (a == "--no-load-speed") fw.no_load_speed = std::stod(val());
      else if (a == "--tau") fw.tau = std::stod(val());
      else if (a == "--watchdog-ms") fw.watchdog_ms = static_cast<uint16_t>(std::stoi(val()));
      else if (a == "--corrupt-rate") faults.corrupt_rx = std::stod(val());
      else if (a == "--corrupt-tx-rate") faults.corrupt_tx = std::stod(val());
      else if (a == "--cut-rx-after") faults.cut_rx_after = std::stod(val());
      else if (a == "--baud") faults.baud = std::stoi(val());
      else if (a == "--require-checked") fw.require_checked = true;
      else if (a == "--ros-time") ros_time = true;
      else if (a == "--sim-wheel-cmd") sim_wheel_cmd = val();
      else if (a == "--seed") faults.seed = static_cast<uint32_t>(std::stoul(val()));
      else if (a == "-h" || a == "--help") { usage(); return 0; }
      else throw std::invalid_argument("unknown option " + a);
    }
  } catch (const std::exception& e) {
    std::cerr << "airboard_emulator: " << e.what() << "\n";
    usage();
    return 2;
  }
  const bool ros_node = ros_time || !sim_wheel_cmd.empty();
  std::unique_ptr<ros::NodeHandle> nh;
  ros::Publisher wheel_pub;
  if (ros_node) {
    ros::init(argc, argv, "airboard_emulator", ros::init_options::NoSigintHandler);
    nh = std::make_unique<ros::NodeHandle>();  // starts the node: /clock is followed from here on
    if (!sim_wheel_cmd.empty()) wheel_pub = nh->advertise<mrt_msgs::WheelCommand>(sim_wheel_cmd, 10);
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::signal(SIGHUP, on_signal);
  try {
    mrt::airboard::PtyEmulator emu(fw, faults, link);
    if (ros_time) emu.set_time_source([] { return ros::Time::now().toSec(); });
    if (!sim_wheel_cmd.empty())
      emu.set_state_observer([&wheel_pub](uint32_t, const std::vector<double>& speeds) {
        mrt_msgs::WheelCommand c;
        c.header.stamp = ros::Time::now();
        c.mode = mrt_msgs::WheelCommand::MODE_SPEED;
        c.speed = speeds;
        wheel_pub.publish(c);
      });
    std::cout << "pty: " << emu.slave_path() << std::endl;
    emu.run(g_stop);
    const auto& s = emu.stats();
    const auto& f = emu.firmware();
    std::cerr << "airboard_emulator: " << f.time_ms() << " ms served, " << f.commands_applied()
              << " commands applied, " << f.commands_rejected() << " rejected, " << f.rx_stats().frames_bad()
              << " bad frames, " << f.watchdog_trips() << " watchdog trips, " << s.bytes_in << " bytes in ("
              << s.bytes_corrupted_in << " corrupted, " << s.bytes_cut_in << " cut), " << s.bytes_out
              << " bytes out (" << s.bytes_dropped_out << " dropped), " << s.late_ticks << " late ticks, "
              << s.paused_ticks << " paused ticks\n";
  } catch (const std::exception& e) {
    std::cerr << "airboard_emulator: " << e.what() << "\n";
    return 1;
  }
  if (ros_node) ros::shutdown();
  return 0;
}
