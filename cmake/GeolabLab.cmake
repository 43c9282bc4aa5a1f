# geolab_add_lab(NN_name)
# Builds one lab twice from the same header and tests:
#   lab_NN        labs/NN_name/src/*.cpp        (the student's code; stubs in a fresh release)
#   lab_NN_sol    solutions/NN_name/src/*.cpp   (the reference, only where solutions/ exists)
# and one test program per variant from tests/NN_name/*.cpp and tests/NN_name/hidden/*.cpp:
#   test_NN_name, test_NN_name_solution
# plus the lab's demo (labs/NN_name/demo.cpp) linked against GEOLAB_VARIANT_<NN>, the variant the program uses.
function(geolab_add_lab lab)
  string(SUBSTRING ${lab} 0 2 nn)
  set(lab_dir ${PROJECT_SOURCE_DIR}/labs/${lab})
  set(sol_dir ${PROJECT_SOURCE_DIR}/solutions/${lab})
  set(test_dir ${PROJECT_SOURCE_DIR}/tests/${lab})

  file(GLOB student_src CONFIGURE_DEPENDS ${lab_dir}/src/*.cpp)
  add_library(lab_${nn} STATIC ${student_src})
  target_include_directories(lab_${nn} PUBLIC ${lab_dir}/include)
  target_link_libraries(lab_${nn} PUBLIC geolab::core)
  # Stubs throw before using their parameters: keep students' warnings about their own code only.
  target_compile_options(lab_${nn} PRIVATE -Wall -Wextra -Wno-unused-parameter -Wno-unused-variable
                                           -Wno-unused-function -Wno-unused-but-set-variable)
  set(variant lab_${nn})

  file(GLOB test_src CONFIGURE_DEPENDS ${test_dir}/*.cpp ${test_dir}/hidden/*.cpp)
  # Tests may check results against Eigen (an independent reference solver; header-only, Debian libeigen3-dev)
  find_package(Eigen3 3.3 REQUIRED NO_MODULE)
  add_executable(test_${lab} ${test_src})
  target_link_libraries(test_${lab} PRIVATE lab_${nn} geolab::test_main Eigen3::Eigen)
  target_include_directories(test_${lab} PRIVATE ${test_dir})

  if(GEOLAB_HAS_SOLUTIONS AND EXISTS ${sol_dir})
    file(GLOB sol_src CONFIGURE_DEPENDS ${sol_dir}/src/*.cpp)
    add_library(lab_${nn}_sol STATIC ${sol_src})
    target_include_directories(lab_${nn}_sol PUBLIC ${lab_dir}/include)
    target_link_libraries(lab_${nn}_sol PUBLIC geolab::core)
    target_compile_options(lab_${nn}_sol PRIVATE -Wall -Wextra)
    add_executable(test_${lab}_solution ${test_src})
    target_link_libraries(test_${lab}_solution PRIVATE lab_${nn}_sol geolab::test_main Eigen3::Eigen)
    target_include_directories(test_${lab}_solution PRIVATE ${test_dir})
    set(variant lab_${nn}_sol)
  endif()
  set(GEOLAB_VARIANT_${nn} ${variant} PARENT_SCOPE)
  set_property(GLOBAL APPEND PROPERTY GEOLAB_VARIANT_LIBS ${variant})

  if(EXISTS ${lab_dir}/demo.cpp)
    add_executable(demo_${lab} ${lab_dir}/demo.cpp)
    target_link_libraries(demo_${lab} PRIVATE ${variant} geolab::render CLI11::CLI11)
  endif()
endfunction()
