# The RoboCup team's rostests (issue 21), included by mrt_robocup's
# CMakeLists.txt (include(test/rostests.cmake OPTIONAL)) inside or outside
# its if(CATKIN_ENABLE_TESTING). Each runs the whole team
# (launch/robocup.launch, ideal vision, no rviz): README "Tests".
if(CATKIN_ENABLE_TESTING)
  find_package(rostest REQUIRED)
  find_package(catkin REQUIRED COMPONENTS mrt_common_ros mrt_msgs nav_msgs roscpp std_msgs xmlrpcpp)
  foreach(t stop removal score)
    add_executable(${PROJECT_NAME}_${t}_rostest EXCLUDE_FROM_ALL test/rostest_${t}.cpp)
    target_include_directories(${PROJECT_NAME}_${t}_rostest PRIVATE ${GTEST_INCLUDE_DIRS} ${catkin_INCLUDE_DIRS})
    target_link_libraries(${PROJECT_NAME}_${t}_rostest ${GTEST_LIBRARIES} ${catkin_LIBRARIES})
    add_dependencies(${PROJECT_NAME}_${t}_rostest ${catkin_EXPORTED_TARGETS})
    if(TARGET player_node)
      add_dependencies(${PROJECT_NAME}_${t}_rostest player_node)
    endif()
    add_dependencies(tests ${PROJECT_NAME}_${t}_rostest)
  endforeach()
  add_rostest(test/stop.test DEPENDENCIES ${PROJECT_NAME}_stop_rostest)
  add_rostest(test/removal.test DEPENDENCIES ${PROJECT_NAME}_removal_rostest)
  # Five seeded runs of the scoring test; the issue asks for 4 of 5.
  foreach(seed 1 2 3 4 5)
    add_rostest(test/score.test ARGS seed:=${seed} DEPENDENCIES ${PROJECT_NAME}_score_rostest)
  endforeach()
endif()
