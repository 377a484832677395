# Node tests: rostest, one scenario per .test file (test/ros/). Included from
# CMakeLists.txt inside if(CATKIN_ENABLE_TESTING). Run them with
#   catkin_make run_tests_rigid_body_sim      (all)
#   rostest rigid_body_sim <name>.test        (one)
find_package(rostest REQUIRED)
# The node publishes /tf without tf2_ros; interface_test reads it back through a
# tf2_ros::Buffer, so tf2_ros is a test dependency only.
find_package(tf2_ros REQUIRED)

set(_rbs_node_gtests
  interface
  constant_force
  body_axes
  wrench_semantics
  bad_input
  services
  timing
  degenerate
  fault
  reconfigure
  outputs
  body_wrenches
  bodies_at_run_time
  properties
  sim_time
  clock_order
  thrusters
  sensors)

foreach(_t ${_rbs_node_gtests})
  add_rostest_gtest(${_t}_test test/ros/${_t}.test test/ros/${_t}_test.cpp)
  if(TARGET ${_t}_test)
    target_include_directories(${_t}_test PRIVATE ${catkin_INCLUDE_DIRS})
    target_link_libraries(${_t}_test ${catkin_LIBRARIES} rigid_body_sim_core)
    add_dependencies(${_t}_test rigid_body_sim_node ${${PROJECT_NAME}_EXPORTED_TARGETS})
  endif()
endforeach()
# clock_order_test runs the node in its own process.
if(TARGET clock_order_test)
  target_link_libraries(clock_order_test rigid_body_sim_ros)
endif()
if(TARGET interface_test)
  target_include_directories(interface_test PRIVATE ${tf2_ros_INCLUDE_DIRS})
  target_link_libraries(interface_test ${tf2_ros_LIBRARIES})
endif()

# Pure-launch / Python tests: they only need the node built.
add_rostest(test/ros/hz.test DEPENDENCIES rigid_body_sim_node)
add_rostest(test/ros/invalid_scene.test DEPENDENCIES rigid_body_sim_node)
# The documents' commands: a check of the text, run by the test command
# (scripts/sanitizers.sh leaves it out: it adds no path of the node's own).
option(RBS_DOCUMENT_TESTS "Run the documents' commands (readme_examples.test)" ON)
if(RBS_DOCUMENT_TESTS)
  add_rostest(test/ros/readme_examples.test DEPENDENCIES rigid_body_sim_node)
endif()
add_rostest(test/ros/respawn.test DEPENDENCIES rigid_body_sim_node)
add_rostest(test/ros/lockstep.test DEPENDENCIES rigid_body_sim_node)
add_rostest(test/ros/lockstep_answers.test DEPENDENCIES rigid_body_sim_node)
add_rostest(test/ros/closed_loop.test DEPENDENCIES rigid_body_sim_node)
add_rostest(test/ros/quadrotor.test DEPENDENCIES rigid_body_sim_node quadrotor_controller
  rigid_body_sim_nodelets rigid_body_sim_example_nodelets)
add_rostest(test/ros/record_replay.test DEPENDENCIES rigid_body_sim_node quadrotor_controller replay)
add_rostest(test/ros/sharded.test DEPENDENCIES rigid_body_sim_node)
# The shards on hosts of their own: network namespaces the test makes (as root).
add_rostest(test/ros/multi_host/multi_host.test DEPENDENCIES rigid_body_sim_node)
add_rostest(test/ros/hostile_input.test DEPENDENCIES rigid_body_sim_node)
add_rostest(test/ros/client.test DEPENDENCIES rigid_body_sim_node)
add_rostest(test/ros/empty_world.test DEPENDENCIES rigid_body_sim_node)
add_rostest(test/ros/body_frames.test DEPENDENCIES rigid_body_sim_node)
add_rostest(test/ros/tf_prefix.test DEPENDENCIES rigid_body_sim_node)
add_rostest(test/ros/clock_rate.test DEPENDENCIES rigid_body_sim_node)
add_rostest(test/ros/drag_wind.test DEPENDENCIES rigid_body_sim_node)
add_rostest(test/ros/start_paused.test DEPENDENCIES rigid_body_sim_node)
add_rostest(test/ros/cpp_examples.test DEPENDENCIES rigid_body_sim_node step_client hold_controller)

# The node's pieces that need no master: message conversions, the per-body
# outputs and the sites' static transforms, the wrench and request checks, the
# scene and IMU noise parsers, the runtime keys' checks and configuration, the bodies
# read from URDF, ~record's queue.
catkin_add_gtest(ros_units_test test/ros/conversions_test.cpp test/ros/wrench_intake_test.cpp
  test/ros/body_state_request_test.cpp test/ros/scene_params_test.cpp
  test/ros/runtime_keys_test.cpp test/ros/runtime_config_test.cpp test/ros/body_outputs_test.cpp
  test/ros/imu_noise_params_test.cpp test/ros/wrench_job_request_test.cpp
  test/ros/yaml_value_test.cpp test/ros/lockstep_gate_test.cpp
  test/ros/state_hash_worker_test.cpp test/ros/urdf_body_test.cpp
  test/ros/urdf_file_policy_test.cpp
  test/ros/wrench_frame_test.cpp test/ros/scene_frames_test.cpp
  test/ros/static_frames_test.cpp test/ros/actuator_command_check_test.cpp
  test/ros/scene_actuators_test.cpp test/ros/scene_sensors_test.cpp
  test/ros/input_recorder_test.cpp)
# urdf_body_test and scene_frames_test read config/quadrotor.urdf from the source tree.
target_compile_definitions(ros_units_test PRIVATE
  RBS_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
# test/common is shared with the core's tests.
target_include_directories(ros_units_test PRIVATE ${catkin_INCLUDE_DIRS} test/common)
target_link_libraries(ros_units_test rigid_body_sim_ros gtest_main)
add_dependencies(ros_units_test ${${PROJECT_NAME}_EXPORTED_TARGETS})

# The wire interface: the md5sums of the messages and services and the
# reconfigure parameters against test/ros/interface_md5.yaml.
catkin_add_gtest(interface_md5_test test/ros/interface_md5_test.cpp)
target_include_directories(interface_md5_test PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(interface_md5_test ${catkin_LIBRARIES} ${YAML_CPP_LIBRARIES} gtest_main)
target_compile_definitions(interface_md5_test PRIVATE RBS_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_dependencies(interface_md5_test ${${PROJECT_NAME}_EXPORTED_TARGETS})

# The C++ client (cmake/client.cmake) against two nodes.
add_rostest_gtest(cpp_client_test test/ros/cpp_client.test test/ros/cpp_client_test.cpp)
if(TARGET cpp_client_test)
  target_link_libraries(cpp_client_test rigid_body_sim_client ${catkin_LIBRARIES})
  add_dependencies(cpp_client_test rigid_body_sim_node)
endif()
