# The RoboCup team's rostests (issue 21), included by mrt_robocup's
# CMakeLists.txt (include(test/rostests.cmake OPTIONAL)) after its
# if(CATKIN_ENABLE_TESTING) block, which finds rostest. Each runs the whole team
# (launch/robocup.launch, ideal vision, no rviz): README "Tests".
if(CATKIN_ENABLE_TESTING)
  # rostest: found by CMakeLists.txt (the match plugin's rostest).
  # The package's catkin components (roscpp, mrt_msgs, nav_msgs, std_msgs,
  # mrt_common_ros) cover the tests; xmlrpcpp comes with roscpp.
  foreach(t stop removal score)
    add_executable(${PROJECT_NAME}_${t}_rostest EXCLUDE_FROM_ALL test/rostest_${t}.cpp)
    target_include_directories(${PROJECT_NAME}_${t}_rostest PRIVATE ${GTEST_INCLUDE_DIRS})
    target_link_libraries(${PROJECT_NAME}_${t}_rostest ${GTEST_LIBRARIES} ${catkin_LIBRARIES})
    add_dependencies(${PROJECT_NAME}_${t}_rostest ${catkin_EXPORTED_TARGETS})
    if(TARGET player_node)
      add_dependencies(${PROJECT_NAME}_${t}_rostest player_node)
    endif()
    add_dependencies(tests ${PROJECT_NAME}_${t}_rostest)
  endforeach()
  add_rostest(test/stop.test DEPENDENCIES ${PROJECT_NAME}_stop_rostest)
  # Removal: a ball job taken over within drop_timeout + one cycle + 0.1 s
  # of the removed robot's last message, play continuing (README "Bringup
  # rostests"); a robot is removed only while a survivor sees the ball. A
  # removal at which no ball job was opportune any more (the ball out of
  # play) says nothing; the test then removes the next ball-job holder (two
  # removals at most).
  add_rostest(test/removal.test DEPENDENCIES ${PROJECT_NAME}_removal_rostest)
  # The scoring criterion (issue 21: the team scores within 120 simulated
  # seconds in at least 4 of 5 seeded runs) as one case: score_seeds.py
  # runs score.test for seeds 1 to 5, each rostest with its own master and
  # its results aside, until the verdict is known (4 scored, or 2 missed),
  # and writes rostest-score_seeds.xml (README "Bringup rostests").
  # One seed by hand: rostest mrt_robocup score.test seed:=N
  catkin_run_tests_target("rostest" "score_seeds" "rostest-score_seeds.xml"
    COMMAND "${PYTHON_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/scripts/score_seeds.py --timeout 450 --out ${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/rostest-score_seeds.xml"
    DEPENDENCIES ${PROJECT_NAME}_score_rostest)
  # 5 runs of at most 450 s wall each (about 25 s when the goal comes early).
  set_tests_properties(_ctest_${PROJECT_NAME}_rostest_score_seeds PROPERTIES TIMEOUT 2400)
endif()

# The bringup's launch files, rviz config and helper scripts (the launch
# files use $(find mrt_robocup)/launch, the rostests and the demo the scripts).
install(DIRECTORY launch DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
catkin_install_python(PROGRAMS scripts/rtf_monitor.py scripts/robocup_summary.py scripts/cpu_profile.py
  scripts/score_seeds.py
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

# The bringup's small nodes (robot.launch, robocup.launch): SCARE's world
# data from MAP's model, and the job/role markers for rviz. (The Debian
# system has no Python visualization_msgs, so a rospy script cannot do it.)
find_package(visualization_msgs REQUIRED)
foreach(n scare_world_node team_markers_node)
  add_executable(${n} src/ros/${n}.cpp)
  target_include_directories(${n} PRIVATE ${visualization_msgs_INCLUDE_DIRS})
  add_dependencies(${n} ${catkin_EXPORTED_TARGETS})
  target_link_libraries(${n} ${catkin_LIBRARIES})
  if(n STREQUAL scare_world_node)
    target_link_libraries(${n} ${PROJECT_NAME}_core)  # team_crisp(), without the simulator
  endif()
  install(TARGETS ${n} RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
endforeach()
