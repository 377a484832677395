# Programs on the C++ client (cmake/client.cmake), installed with the node:
# the quadrotor example's controller (launch/quadrotor.launch), also as a
# nodelet, and the two programs doc/testing.md quotes.

# The controllers, each built once for its program and its nodelet; the
# quadrotor's mixer turns thrust and torques into its rotors' thrusts.
add_library(rotor_mixer STATIC src/examples/rotor_mixer.cpp)
set_target_properties(rotor_mixer PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_include_directories(rotor_mixer SYSTEM PUBLIC ${EIGEN3_INCLUDE_DIR})
add_library(quadrotor_control STATIC src/examples/quadrotor_controller.cpp)
set_target_properties(quadrotor_control PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_link_libraries(quadrotor_control rotor_mixer rigid_body_sim_client ${catkin_LIBRARIES})
add_dependencies(quadrotor_control ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})

add_library(hold_control STATIC src/examples/hold_controller.cpp)
set_target_properties(hold_control PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_include_directories(hold_control SYSTEM PUBLIC ${EIGEN3_INCLUDE_DIR})
target_link_libraries(hold_control rigid_body_sim_client ${catkin_LIBRARIES})
add_dependencies(hold_control ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})

add_executable(quadrotor_controller src/examples/quadrotor_controller_main.cpp)
target_link_libraries(quadrotor_controller quadrotor_control)
add_executable(hold_controller src/examples/hold_controller_main.cpp)
target_link_libraries(hold_controller hold_control)
# rigid_body_sim/QuadrotorControllerNodelet and HoldControllerNodelet
# (nodelet_plugins.xml).
add_library(rigid_body_sim_example_nodelets src/examples/quadrotor_controller_nodelet.cpp
  src/examples/hold_controller_nodelet.cpp)
target_link_libraries(rigid_body_sim_example_nodelets quadrotor_control hold_control)

add_executable(step_client src/examples/step_client.cpp)
target_include_directories(step_client SYSTEM PRIVATE ${EIGEN3_INCLUDE_DIR})
target_link_libraries(step_client rigid_body_sim_client ${catkin_LIBRARIES})
add_dependencies(step_client ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})
install(TARGETS quadrotor_controller hold_controller step_client rigid_body_sim_example_nodelets
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(rotor_mixer_test test/examples/rotor_mixer_test.cpp)
  target_include_directories(rotor_mixer_test PRIVATE src/examples)
  target_link_libraries(rotor_mixer_test rotor_mixer gtest_main)
endif()

# rviz arrows for thrusters (launch/quadrotor.launch with rviz:=true); in
# the devel space rosrun and roslaunch find it in scripts/.
install(PROGRAMS scripts/thrust_markers.py
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
