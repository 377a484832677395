# The ROS node over the core: a library (parameters, conversions, the node
# class) and a thin executable. Included from CMakeLists.txt after the core.
include_directories(include ${catkin_INCLUDE_DIRS})
# ~spawn_body reads one scene entry from YAML text: libyaml parses it (bounded
# lookahead), yaml-cpp converts its odd scalars as rosparam would.
find_package(yaml-cpp REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(LIBYAML REQUIRED yaml-0.1)
# Bodies from URDF: ROS's urdf parser (urdfdom underneath) reads the XML, and
# roslib's ros::package resolves package:// paths. Only src/ros/urdf_body.cpp
# and src/ros/urdf_file_policy.cpp include them: no installed header does, so
# they are not exported.
find_package(urdf REQUIRED)
find_package(roslib REQUIRED)

add_library(rigid_body_sim_ros
  src/ros/param_values.cpp
  src/ros/scene_settings.cpp
  src/ros/scene_bodies.cpp
  src/ros/body_graph_table.cpp
  src/ros/scene_map_list.cpp
  src/ros/scene_actuators.cpp
  src/ros/scene_sensors.cpp
  src/ros/site_sensors.cpp
  src/ros/scene_frames.cpp
  src/ros/scene_inertial.cpp
  src/ros/scene_urdf.cpp
  src/ros/scene_params.cpp
  src/ros/conversions.cpp
  src/ros/body_outputs.cpp
  src/ros/imu_noise_params.cpp
  src/ros/wrench_intake.cpp
  src/ros/actuator_command_check.cpp
  src/ros/wrench_frame.cpp
  src/ros/body_state_request.cpp
  src/ros/wrench_job_request.cpp
  src/ros/yaml_value.cpp
  src/ros/yaml_sizing.cpp
  src/ros/urdf_body.cpp
  src/ros/urdf_file_policy.cpp
  src/ros/regular_file.cpp
  src/ros/master_param.cpp
  src/ros/body_topics.cpp
  src/ros/log_thread.cpp
  src/ros/held_joint_states.cpp
  src/ros/state_publisher.cpp
  src/ros/clock_publisher.cpp
  src/ros/static_frames.cpp
  src/ros/node_diagnostics.cpp
  src/ros/runtime_keys.cpp
  src/ros/runtime_config.cpp
  src/ros/lockstep_gate.cpp
  src/ros/lockstep_publishers.cpp
  src/ros/state_hash_worker.cpp
  src/ros/request_lane.cpp
  src/ros/step_lattice.cpp
  src/ros/lockstep_driver.cpp
  src/ros/input_recorder.cpp
  src/ros/recorded_input.cpp
  src/ros/recorded_parameters.cpp
  src/ros/recording.cpp
  src/ros/replay.cpp
  src/ros/world_editor.cpp
  src/ros/service_front.cpp
  src/ros/runtime_settings.cpp
  src/ros/simulation_node.cpp
  src/ros/node_handles.cpp
  src/ros/simulation_runner.cpp)
# The ROS headers come from include_directories() above here and from
# catkin_package() for dependent packages: no absolute path in the interface.
target_include_directories(rigid_body_sim_ros PUBLIC include PRIVATE ${catkin_INCLUDE_DIRS}
  ${urdf_INCLUDE_DIRS} ${roslib_INCLUDE_DIRS})
target_link_libraries(rigid_body_sim_ros rigid_body_sim_core ${catkin_LIBRARIES} ${YAML_CPP_LIBRARIES}
  ${LIBYAML_LIBRARIES} ${urdf_LIBRARIES} ${roslib_LIBRARIES})
add_dependencies(rigid_body_sim_ros
  ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})

add_executable(rigid_body_sim_node src/rigid_body_sim_node.cpp)
target_link_libraries(rigid_body_sim_node rigid_body_sim_ros rigid_body_sim_core ${catkin_LIBRARIES})
add_dependencies(rigid_body_sim_node
  ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})

# The node as a nodelet (nodelet_plugins.xml): rigid_body_sim/SimulationNodelet.
add_library(rigid_body_sim_nodelets src/ros/simulation_nodelet.cpp)
target_link_libraries(rigid_body_sim_nodelets rigid_body_sim_ros rigid_body_sim_core
  ${catkin_LIBRARIES})
add_dependencies(rigid_body_sim_nodelets
  ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})

# replay: a ~record bag done again without the node (src/replay_main.cpp).
add_executable(replay src/replay_main.cpp)
target_link_libraries(replay rigid_body_sim_ros rigid_body_sim_core ${catkin_LIBRARIES})
add_dependencies(replay ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})

install(TARGETS rigid_body_sim_core rigid_body_sim_ros rigid_body_sim_nodelets rigid_body_sim_node
  replay
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
install(DIRECTORY include/${PROJECT_NAME}/
  DESTINATION ${CATKIN_PACKAGE_INCLUDE_DESTINATION})
install(DIRECTORY launch config
  DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
install(FILES nodelet_plugins.xml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
# launch/sharded.launch's launch-prefix: $(find rigid_body_sim)/scripts/on_core.sh
# resolves to this copy in an install space.
install(PROGRAMS scripts/on_core.sh
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
