# Benchmarks (bench/), built with -DRBS_BUILD_BENCH=ON by scripts/bench.sh.
find_package(benchmark REQUIRED)
include(${CMAKE_CURRENT_LIST_DIR}/bench_peers.cmake)

add_executable(work_precision bench/work_precision.cpp bench/scene_load.cpp)
target_link_libraries(work_precision rigid_body_sim_bench_peers rigid_body_sim_core)

add_executable(stability_stress bench/stability_stress.cpp)
# The stress bodies and loads are the test suite's (test/core/stress_cases.h).
target_include_directories(stability_stress PRIVATE test/core)
target_link_libraries(stability_stress rigid_body_sim_core)

add_executable(throughput_bench bench/throughput_bench.cpp)
target_link_libraries(throughput_bench rigid_body_sim_core benchmark::benchmark)

# Floods the node's wrench topics (scripts/flood.sh).
add_executable(wrench_flood bench/wrench_flood.cpp)
target_include_directories(wrench_flood PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(wrench_flood ${catkin_LIBRARIES})
add_dependencies(wrench_flood ${${PROJECT_NAME}_EXPORTED_TARGETS})

# The machine's wake-up jitter, the floor under the node's overruns (bench/node_load.py).
add_executable(wake_jitter bench/wake_jitter.cpp)

# A robot description of N links loaded as one body.
add_executable(urdf_load_bench bench/urdf_load_bench.cpp)
target_link_libraries(urdf_load_bench rigid_body_sim_ros benchmark::benchmark)
