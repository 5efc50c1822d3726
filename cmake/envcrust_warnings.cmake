# envcrust_set_warnings(target): per-target warning flags (never global CMAKE_CXX_FLAGS).
function(envcrust_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(ENVCRUST_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# envcrust_add_module(name SOURCES ... DEPS ...): one static library per module folder.
function(envcrust_add_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(envcrust_${name} STATIC)
  target_sources(envcrust_${name} PRIVATE ${ARG_SOURCES})
  target_include_directories(envcrust_${name}
    PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_libraries(envcrust_${name} PUBLIC envcrust_core ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  envcrust_set_warnings(envcrust_${name})
  # Installed as envcrust::<name> (src/CMakeLists.txt exports every module).
  set_target_properties(envcrust_${name} PROPERTIES EXPORT_NAME ${name})
  add_library(envcrust::${name} ALIAS envcrust_${name})
endfunction()
