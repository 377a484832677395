# The C++ client other packages link through catkin (include/rigid_body_sim/
# client, doc/testing.md): SimClient over the node's services and topics and
# the LockstepController base. It uses only the package's messages and the
# core's state hash. Included from CMakeLists.txt after the core.
add_library(rigid_body_sim_client
  src/client/sim_client.cpp
  src/client/lockstep_controller.cpp)
target_include_directories(rigid_body_sim_client PUBLIC include PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(rigid_body_sim_client rigid_body_sim_core ${catkin_LIBRARIES})
add_dependencies(rigid_body_sim_client
  ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})

install(TARGETS rigid_body_sim_client
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
