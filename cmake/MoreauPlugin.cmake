# moreau_add_plugin(KIND NAME SOURCES file... [LIBRARIES lib...] [OUTPUT_DIR dir] [NO_INSTALL])
#
# Builds plugin NAME of kind KIND as the shared library libmoreau_<KIND>_<NAME>.so, the
# file name the kernel looks for when a scene names (KIND, NAME). Also defines the object
# library moreau_<KIND>_<NAME>_obj, which tests link to reach the plugin's classes.
# Used by moreau itself and, through find_package(moreau), by third-party plugins.
function(moreau_add_plugin KIND NAME)
  cmake_parse_arguments(ARG "NO_INSTALL" "OUTPUT_DIR" "SOURCES;LIBRARIES" ${ARGN})
  set(target moreau_${KIND}_${NAME})
  add_library(${target}_obj OBJECT ${ARG_SOURCES})
  set_target_properties(${target}_obj PROPERTIES
    POSITION_INDEPENDENT_CODE ON CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  target_link_libraries(${target}_obj PUBLIC moreau::sdk ${ARG_LIBRARIES})
  # GCC marks some inline statics STB_GNU_UNIQUE, which makes a library impossible to
  # unload; plugins must unload once their last object is gone.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target}_obj PRIVATE -fno-gnu-unique)
  endif()
  add_library(${target} MODULE $<TARGET_OBJECTS:${target}_obj>)
  target_link_libraries(${target} PRIVATE moreau::sdk ${ARG_LIBRARIES})
  set_target_properties(${target} PROPERTIES
    PREFIX "lib" OUTPUT_NAME ${target}
    CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  if(ARG_OUTPUT_DIR)
    set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${ARG_OUTPUT_DIR})
  elseif(DEFINED MOREAU_PLUGIN_OUTPUT_DIR)
    set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${MOREAU_PLUGIN_OUTPUT_DIR})
  endif()
  if(DEFINED MOREAU_PLUGIN_INSTALL_DIR AND NOT ARG_NO_INSTALL)
    install(TARGETS ${target} LIBRARY DESTINATION ${MOREAU_PLUGIN_INSTALL_DIR})
  endif()
endfunction()

# moreau_add_static_library(NAME SOURCES file... [LIBRARIES lib...])
#
# A static library of code shared by plugins (and reached by tests), compiled
# position-independent with the plugins' hidden visibility, so it can be linked into them.
function(moreau_add_static_library NAME)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBRARIES" ${ARGN})
  add_library(${NAME} STATIC ${ARG_SOURCES})
  set_target_properties(${NAME} PROPERTIES
    POSITION_INDEPENDENT_CODE ON CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  target_include_directories(${NAME} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_libraries(${NAME} PUBLIC ${ARG_LIBRARIES})
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${NAME} PRIVATE -fno-gnu-unique)
  endif()
endfunction()
