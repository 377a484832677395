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
