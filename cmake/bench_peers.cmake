# The peer engines of the work-precision benchmark: finds MuJoCo, Bullet,
# ODE, Simbody, DART and Boost.Odeint as Debian packages them
# (scripts/bench.sh installs them), and builds rigid_body_sim_bench_peers
# from bench/scene.cpp, the shared peer files, the closed-form peer and the
# peers of the engines that were found, with RBS_HAVE_<ENGINE> defined for
# each. A missing engine is not an error: its benchmark lines are skipped and
# MakePeers names them. Needs the target rigid_body_sim_core.
#
# RBS_BENCH_BULLET_FLOAT32: link Bullet's default single-precision build
# instead of the double-precision one (Debian ships both).

option(RBS_BENCH_BULLET_FLOAT32 "Bench: use Bullet's single-precision libraries" OFF)

find_package(PkgConfig QUIET)
set(_rbs_peer_dir ${CMAKE_CURRENT_LIST_DIR}/../bench)
set(_rbs_peer_sources
  ${_rbs_peer_dir}/scene.cpp
  ${_rbs_peer_dir}/peers/peer_loads.cpp
  ${_rbs_peer_dir}/peers/make_peers.cpp
  ${_rbs_peer_dir}/peers/closed_form_peer.cpp)
set(_rbs_peer_definitions)
set(_rbs_peer_libraries)

# MuJoCo 2.2.2: no .pc file; libmujoco-dev ships headers in /usr/include/mujoco
# and an imported target mujoco::mujoco (whose interface also names qhull's
# include directory), so plain find_path/find_library is the robust way.
find_path(RBS_MUJOCO_INCLUDE_DIR mujoco/mujoco.h)
find_library(RBS_MUJOCO_LIBRARY mujoco)
if(RBS_MUJOCO_INCLUDE_DIR AND RBS_MUJOCO_LIBRARY)
  message(STATUS "bench: MuJoCo found (${RBS_MUJOCO_LIBRARY})")
  list(APPEND _rbs_peer_sources ${_rbs_peer_dir}/peers/mujoco_peer.cpp)
  list(APPEND _rbs_peer_definitions RBS_HAVE_MUJOCO)
  add_library(rbs_bench_mujoco INTERFACE)
  target_include_directories(rbs_bench_mujoco SYSTEM INTERFACE ${RBS_MUJOCO_INCLUDE_DIR})
  target_link_libraries(rbs_bench_mujoco INTERFACE ${RBS_MUJOCO_LIBRARY})
  list(APPEND _rbs_peer_libraries rbs_bench_mujoco)
else()
  message(STATUS "bench: MuJoCo not found (apt-get install libmujoco-dev) - its lines are skipped")
endif()

# Bullet 3.24: bullet.pc (float32) and bullet-float64.pc (BT_USE_DOUBLE_PRECISION
# in its Cflags, which must reach every file that includes Bullet's headers).
if(RBS_BENCH_BULLET_FLOAT32)
  set(_rbs_bullet_module bullet)
else()
  set(_rbs_bullet_module bullet-float64)
endif()
if(PKG_CONFIG_FOUND)
  pkg_check_modules(RBS_BULLET QUIET IMPORTED_TARGET ${_rbs_bullet_module})
endif()
if(RBS_BULLET_FOUND)
  message(STATUS "bench: Bullet found (${_rbs_bullet_module} ${RBS_BULLET_VERSION})")
  list(APPEND _rbs_peer_sources ${_rbs_peer_dir}/peers/bullet_peer.cpp)
  list(APPEND _rbs_peer_definitions RBS_HAVE_BULLET)
  list(APPEND _rbs_peer_libraries PkgConfig::RBS_BULLET)
else()
  message(STATUS "bench: Bullet not found (apt-get install libbullet-dev) - its lines are skipped")
endif()

# ODE 0.16: ode.pc; Debian builds it with dDOUBLE, which ode/precision.h selects.
if(PKG_CONFIG_FOUND)
  pkg_check_modules(RBS_ODE QUIET IMPORTED_TARGET ode)
endif()
if(RBS_ODE_FOUND)
  message(STATUS "bench: ODE found (${RBS_ODE_VERSION})")
  list(APPEND _rbs_peer_sources ${_rbs_peer_dir}/peers/ode_peer.cpp)
  list(APPEND _rbs_peer_definitions RBS_HAVE_ODE)
  list(APPEND _rbs_peer_libraries PkgConfig::RBS_ODE)
else()
  message(STATUS "bench: ODE not found (apt-get install libode-dev) - its lines are skipped")
endif()

# Simbody 3.7: SimbodyConfig.cmake, whose Simbody_LIBRARIES are imported targets.
find_package(Simbody QUIET CONFIG)
if(Simbody_FOUND)
  message(STATUS "bench: Simbody found (${Simbody_VERSION})")
  list(APPEND _rbs_peer_sources ${_rbs_peer_dir}/peers/simbody_peer.cpp)
  list(APPEND _rbs_peer_definitions RBS_HAVE_SIMBODY)
  add_library(rbs_bench_simbody INTERFACE)
  target_include_directories(rbs_bench_simbody SYSTEM INTERFACE ${Simbody_INCLUDE_DIR})
  target_link_libraries(rbs_bench_simbody INTERFACE ${Simbody_LIBRARIES})
  list(APPEND _rbs_peer_libraries rbs_bench_simbody)
else()
  message(STATUS "bench: Simbody not found (apt-get install libsimbody-dev) - its lines are skipped")
endif()

# DART 6.12: DARTConfig.cmake with the imported target `dart` (dynamics and
# simulation; no optional component is needed).
find_package(DART 6 QUIET CONFIG)
if(DART_FOUND)
  message(STATUS "bench: DART found (${DART_VERSION})")
  list(APPEND _rbs_peer_sources ${_rbs_peer_dir}/peers/dart_peer.cpp)
  list(APPEND _rbs_peer_definitions RBS_HAVE_DART)
  list(APPEND _rbs_peer_libraries dart)
else()
  message(STATUS "bench: DART not found (apt-get install libdart-dev) - its lines are skipped")
endif()

# Boost.Odeint: header-only, part of Boost's headers (libboost-dev).
find_path(RBS_ODEINT_INCLUDE_DIR boost/numeric/odeint.hpp)
if(RBS_ODEINT_INCLUDE_DIR)
  message(STATUS "bench: Boost.Odeint found (${RBS_ODEINT_INCLUDE_DIR})")
  list(APPEND _rbs_peer_sources ${_rbs_peer_dir}/peers/odeint_peer.cpp)
  list(APPEND _rbs_peer_definitions RBS_HAVE_ODEINT)
  add_library(rbs_bench_odeint INTERFACE)
  target_include_directories(rbs_bench_odeint SYSTEM INTERFACE ${RBS_ODEINT_INCLUDE_DIR})
  list(APPEND _rbs_peer_libraries rbs_bench_odeint)
else()
  message(STATUS "bench: Boost.Odeint not found (apt-get install libboost-dev) - its lines are skipped")
endif()

add_library(rigid_body_sim_bench_peers STATIC ${_rbs_peer_sources})
target_compile_features(rigid_body_sim_bench_peers PUBLIC cxx_std_17)
target_include_directories(rigid_body_sim_bench_peers PUBLIC ${_rbs_peer_dir})
target_compile_definitions(rigid_body_sim_bench_peers PUBLIC ${_rbs_peer_definitions})
target_link_libraries(rigid_body_sim_bench_peers PUBLIC rigid_body_sim_core PRIVATE ${_rbs_peer_libraries})
