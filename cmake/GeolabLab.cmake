# geolab_add_lab(NN_name)
# Builds one lab twice from the same header and tests:
#   lab_NN        labs/NN_name/src/*.cpp        (the student's code; stubs in a fresh release)
#   lab_NN_sol    solutions/NN_name/src/*.cpp   (the reference, only where solutions/ exists)
# and one test program per variant from tests/NN_name/*.cpp and tests/NN_name/hidden/*.cpp:
#   test_NN_name, test_NN_name_solution   (with a GEOLAB_BOUNDARY list: the performers, which record)
#   judge_NN_name                         (with a GEOLAB_BOUNDARY list: tests + given code + replay, no student code)
# plus the lab's demo (labs/NN_name/demo.cpp) linked against GEOLAB_VARIANT_<NN>, the variant the program uses,
# and in the instructor's tree also demo_NN_name_stubs, the same objects linked against the untouched stubs
# (tests/demos checks that every demo runs on them).
# geolab_add_boundary(ID API_HEADER INCLUDE_DIR OUT_DIR)
# The record and replay thunks of the GEOLAB_BOUNDARY list in API_HEADER (a header under INCLUDE_DIR):
#   OUT_DIR/recorder.o  the performer's (each thunk defines a student function, records, calls geolab_student_LINE)
#   OUT_DIR/replayer.o  the judge's (each thunk defines a student function and answers from the recording)
#   OUT_DIR/student.syms  the renaming of the student's objects (objcopy --redefine-syms)
function(geolab_add_boundary id api_header include_dir bdir)
  file(RELATIVE_PATH api_rel ${include_dir} ${api_header})
  foreach(role record replay)
    add_library(boundary_${id}_${role} OBJECT ${PROJECT_SOURCE_DIR}/lib/src/grading/boundary_shim.cpp)
    target_compile_definitions(boundary_${id}_${role} PRIVATE GEOLAB_BOUNDARY_ROLE=${role}
                                                              "GEOLAB_LAB_HEADER=<${api_rel}>")
    target_include_directories(boundary_${id}_${role} PRIVATE ${include_dir})
    target_link_libraries(boundary_${id}_${role} PRIVATE geolab::core doctest::doctest)
  endforeach()
  target_compile_definitions(boundary_${id}_replay PRIVATE _GLIBCXX_ASSERTIONS)
  add_custom_command(
    OUTPUT ${bdir}/recorder.o ${bdir}/replayer.o ${bdir}/student.syms
    COMMAND ${CMAKE_COMMAND} -DMODE=shims "-DRECORD=$<TARGET_OBJECTS:boundary_${id}_record>"
            "-DREPLAY=$<TARGET_OBJECTS:boundary_${id}_replay>" -DOUT=${bdir} -DOBJDUMP=${CMAKE_OBJDUMP}
            -DOBJCOPY=${CMAKE_OBJCOPY} -P ${PROJECT_SOURCE_DIR}/cmake/GeolabBoundary.cmake
    DEPENDS boundary_${id}_record boundary_${id}_replay "$<TARGET_OBJECTS:boundary_${id}_record>"
            "$<TARGET_OBJECTS:boundary_${id}_replay>" ${PROJECT_SOURCE_DIR}/cmake/GeolabBoundary.cmake
    COMMENT "boundary ${id}: record and replay thunks")
  set_source_files_properties(${bdir}/recorder.o ${bdir}/replayer.o PROPERTIES EXTERNAL_OBJECT TRUE GENERATED TRUE)
endfunction()

# geolab_performer_library(LIB OUT_DIR): OUT_DIR/libLIB_performer.a, the static library LIB with each boundary
# function renamed to geolab_student_LINE (definitions and the calls among them), and a target LIB_performer.
function(geolab_performer_library v bdir)
  add_custom_command(
    OUTPUT ${bdir}/lib${v}_performer.a
    COMMAND ${CMAKE_COMMAND} -DMODE=rename "-DIN=$<TARGET_FILE:${v}>" -DOUT=${bdir}/lib${v}_performer.a
            -DSYMS=${bdir}/student.syms -DOBJCOPY=${CMAKE_OBJCOPY} -P ${PROJECT_SOURCE_DIR}/cmake/GeolabBoundary.cmake
    DEPENDS ${v} "$<TARGET_FILE:${v}>" ${bdir}/student.syms
    COMMENT "${v} for the performer")
  add_custom_target(${v}_performer DEPENDS ${bdir}/lib${v}_performer.a)
endfunction()

function(geolab_add_lab lab)
  string(SUBSTRING ${lab} 0 2 nn)
  set(lab_dir ${PROJECT_SOURCE_DIR}/labs/${lab})
  set(sol_dir ${PROJECT_SOURCE_DIR}/solutions/${lab})
  set(test_dir ${PROJECT_SOURCE_DIR}/tests/${lab})

  file(GLOB student_src CONFIGURE_DEPENDS ${lab_dir}/src/*.cpp)
  add_library(lab_${nn} STATIC ${student_src})
  target_include_directories(lab_${nn} PUBLIC ${lab_dir}/include)
  target_link_libraries(lab_${nn} PUBLIC geolab::core geolab::checks)  # checks: exact predicates a lab may use
  # Stubs throw before using their parameters: keep students' warnings about their own code only.
  target_compile_options(lab_${nn} PRIVATE -Wall -Wextra -Wno-unused-parameter -Wno-unused-variable
                                           -Wno-unused-function -Wno-unused-but-set-variable)
  set(variant lab_${nn})

  file(GLOB test_src CONFIGURE_DEPENDS ${test_dir}/*.cpp ${test_dir}/hidden/*.cpp)
  # Tests may check results against Eigen (an independent reference solver; header-only, Debian libeigen3-dev)
  find_package(Eigen3 3.3 REQUIRED NO_MODULE)

  # The lab's grading boundary: the first header under include/ with a GEOLAB_BOUNDARY list (geolab/boundary.hpp).
  file(GLOB_RECURSE lab_headers ${lab_dir}/include/*.hpp)
  set(api_header "")
  foreach(h IN LISTS lab_headers)
    file(STRINGS ${h} has_list REGEX "^#ifdef GEOLAB_BOUNDARY$")
    if(has_list AND NOT api_header)
      set(api_header ${h})
    endif()
  endforeach()

  # A lab whose headers include the drawing layer (lab 08's voxelization through OSMesa) links it too.
  set(lab_render_link "")
  foreach(h IN LISTS lab_headers)
    file(STRINGS ${h} uses_render REGEX "^#include \"geolab/render/")
    if(uses_render AND TARGET geolab_render)
      set(lab_render_link geolab::render)
    endif()
  endforeach()
  if(lab_render_link)
    target_link_libraries(lab_${nn} PUBLIC ${lab_render_link})
  endif()

  if(NOT api_header)
    # No boundary list: each test program decides its own verdicts (reported as "verdict not isolated").
    add_executable(test_${lab} ${test_src})
    target_link_libraries(test_${lab} PRIVATE lab_${nn} geolab::test_main Eigen3::Eigen)
    target_include_directories(test_${lab} PRIVATE ${test_dir})
  else()
    # Record and replay (docs/architecture.md): the performers test_NN_name[_solution] run the student's (or the
    # reference) code and record every call across the boundary; the judge judge_NN_name, with the same tests,
    # the lab's given code and no student code, replays the recording and decides the verdict.
    set(bdir ${PROJECT_BINARY_DIR}/boundary/${lab})
    geolab_add_boundary(${nn} ${api_header} ${lab_dir}/include ${bdir})

    # The tests, compiled once for both performers and the judge, with the standard library's assertions: hostile
    # answers that make a test index out of range abort the judge (in a performer they only stop the student's own
    # run). The assertions change no layout, so these objects link with code built without them.
    add_library(tests_${nn} OBJECT ${test_src})
    target_include_directories(tests_${nn} PRIVATE ${test_dir} ${lab_dir}/include)
    target_link_libraries(tests_${nn} PRIVATE geolab::core geolab::test_main Eigen3::Eigen)
    target_compile_definitions(tests_${nn} PRIVATE _GLIBCXX_ASSERTIONS)

    set(lab_variants lab_${nn})
    if(GEOLAB_HAS_SOLUTIONS AND EXISTS ${sol_dir})
      list(APPEND lab_variants lab_${nn}_sol)
    endif()
    foreach(v IN LISTS lab_variants)
      geolab_performer_library(${v} ${bdir})
      if(v STREQUAL "lab_${nn}")
        set(program test_${lab})
      else()
        set(program test_${lab}_solution)
      endif()
      add_executable(${program} $<TARGET_OBJECTS:tests_${nn}> ${bdir}/recorder.o)
      target_link_libraries(${program} PRIVATE ${bdir}/lib${v}_performer.a
                                               $<TARGET_PROPERTY:${v},INTERFACE_LINK_LIBRARIES> geolab::test_main
                                               Eigen3::Eigen)
      add_dependencies(${program} ${v}_performer)
      set_property(TARGET ${program} APPEND PROPERTY LINK_DEPENDS ${bdir}/lib${v}_performer.a)
    endforeach()

    # The judge: the same test objects, the lab's GIVEN files (compiled with the assertions too), the replayer.
    # labs/NN_name/given.txt lists them (the grader and `geolab release --check` read the same list).
    set(given_src "")
    if(EXISTS ${lab_dir}/given.txt)
      file(STRINGS ${lab_dir}/given.txt given_lines REGEX "^[^#]")
      foreach(g IN LISTS given_lines)
        string(STRIP "${g}" g)
        if(g)
          list(APPEND given_src ${lab_dir}/src/${g})
        endif()
      endforeach()
    endif()
    add_executable(judge_${lab} $<TARGET_OBJECTS:tests_${nn}> ${given_src} ${bdir}/replayer.o)
    target_include_directories(judge_${lab} PRIVATE ${test_dir} ${lab_dir}/include)
    target_link_libraries(judge_${lab} PRIVATE $<TARGET_PROPERTY:lab_${nn},INTERFACE_LINK_LIBRARIES> geolab::test_main
                                                     Eigen3::Eigen)
    target_compile_definitions(judge_${lab} PRIVATE _GLIBCXX_ASSERTIONS)
  endif()

  if(GEOLAB_HAS_SOLUTIONS AND EXISTS ${sol_dir})
    file(GLOB sol_src CONFIGURE_DEPENDS ${sol_dir}/src/*.cpp)
    add_library(lab_${nn}_sol STATIC ${sol_src})
    target_include_directories(lab_${nn}_sol PUBLIC ${lab_dir}/include)
    target_link_libraries(lab_${nn}_sol PUBLIC geolab::core geolab::checks ${lab_render_link})
    target_compile_options(lab_${nn}_sol PRIVATE -Wall -Wextra)
    if(NOT api_header)
      add_executable(test_${lab}_solution ${test_src})
      target_link_libraries(test_${lab}_solution PRIVATE lab_${nn}_sol geolab::test_main Eigen3::Eigen)
      target_include_directories(test_${lab}_solution PRIVATE ${test_dir})
    endif()
    set(variant lab_${nn}_sol)
  endif()
  set(GEOLAB_VARIANT_${nn} ${variant} PARENT_SCOPE)
  set_property(GLOBAL APPEND PROPERTY GEOLAB_VARIANT_LIBS ${variant})

  if(EXISTS ${lab_dir}/demo.cpp)
    add_library(demo_${nn}_obj OBJECT ${lab_dir}/demo.cpp)
    target_link_libraries(demo_${nn}_obj PRIVATE lab_${nn} geolab::render CLI11::CLI11)  # (headers only)
    add_executable(demo_${lab} $<TARGET_OBJECTS:demo_${nn}_obj>)
    target_link_libraries(demo_${lab} PRIVATE ${variant} geolab::render CLI11::CLI11)
    if(NOT variant STREQUAL "lab_${nn}")
      add_executable(demo_${lab}_stubs $<TARGET_OBJECTS:demo_${nn}_obj>)
      target_link_libraries(demo_${lab}_stubs PRIVATE lab_${nn} geolab::render CLI11::CLI11)
    endif()
  endif()
endfunction()
