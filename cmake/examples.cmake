# Programs on the C++ client (cmake/client.cmake), installed with the node:
# the quadrotor example's controller (launch/quadrotor.launch) and the two
# programs doc/testing.md quotes.
foreach(_example quadrotor_controller hold_controller step_client)
  add_executable(${_example} src/examples/${_example}.cpp)
  target_include_directories(${_example} SYSTEM PRIVATE ${EIGEN3_INCLUDE_DIR})
  target_link_libraries(${_example} rigid_body_sim_client ${catkin_LIBRARIES})
  add_dependencies(${_example} ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})
endforeach()
install(TARGETS quadrotor_controller hold_controller step_client
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

# The quadrotor's mixer: thrust and torques to its rotors' thrusts.
add_library(rotor_mixer STATIC src/examples/rotor_mixer.cpp)
target_include_directories(rotor_mixer SYSTEM PUBLIC ${EIGEN3_INCLUDE_DIR})
target_link_libraries(quadrotor_controller rotor_mixer)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(rotor_mixer_test test/examples/rotor_mixer_test.cpp)
  target_include_directories(rotor_mixer_test PRIVATE src/examples)
  target_link_libraries(rotor_mixer_test rotor_mixer gtest_main)
endif()

# rviz arrows for thrusters (launch/quadrotor.launch with rviz:=true); in
# the devel space rosrun and roslaunch find it in scripts/.
install(PROGRAMS scripts/thrust_markers.py
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
