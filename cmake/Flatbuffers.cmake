# Compiles FlatBuffers schemas into C++ headers and binary schemas (.bfbs), in the build tree only.
#   chatsim_flatbuffers(TARGET name SCHEMAS a.fbs b.fbs ROOT_SCHEMA root.fbs)
# Creates an INTERFACE library `name` whose include path holds the generated headers, and
# writes the root schema's .bfbs (with every included type) to ${CMAKE_BINARY_DIR}/share/chatsim/msgs.
function(chatsim_flatbuffers)
  cmake_parse_arguments(ARG "" "TARGET;ROOT_SCHEMA" "SCHEMAS" ${ARGN})
  set(gen_dir ${CMAKE_BINARY_DIR}/gen)
  set(out_dir ${gen_dir}/msgs)
  set(bfbs_dir ${CMAKE_BINARY_DIR}/share/chatsim/msgs)
  set(headers)
  set(abs_schemas)
  foreach(schema ${ARG_SCHEMAS})
    get_filename_component(abs ${schema} ABSOLUTE)
    get_filename_component(stem ${schema} NAME_WE)
    list(APPEND abs_schemas ${abs})
    list(APPEND headers ${out_dir}/${stem}_generated.h)
  endforeach()
  get_filename_component(root_abs ${ARG_ROOT_SCHEMA} ABSOLUTE)
  get_filename_component(root_stem ${ARG_ROOT_SCHEMA} NAME_WE)
  get_filename_component(schema_dir ${root_abs} DIRECTORY)
  set(bfbs ${bfbs_dir}/${root_stem}.bfbs)

  add_custom_command(
    OUTPUT ${headers}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${out_dir}
    COMMAND flatbuffers::flatc --cpp --scoped-enums --reflect-names --gen-mutable
            -I ${schema_dir} -o ${out_dir} ${abs_schemas}
    DEPENDS ${abs_schemas}
    COMMENT "flatc: generating C++ for ${ARG_TARGET}"
    VERBATIM)
  add_custom_command(
    OUTPUT ${bfbs}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${bfbs_dir}
    COMMAND flatbuffers::flatc -b --schema --bfbs-comments --bfbs-builtins
            -I ${schema_dir} -o ${bfbs_dir} ${root_abs}
    DEPENDS ${abs_schemas}
    COMMENT "flatc: binary schema ${root_stem}.bfbs"
    VERBATIM)
  add_custom_target(${ARG_TARGET}_gen DEPENDS ${headers} ${bfbs})
  add_library(${ARG_TARGET} INTERFACE)
  add_dependencies(${ARG_TARGET} ${ARG_TARGET}_gen)
  target_include_directories(${ARG_TARGET} SYSTEM INTERFACE ${gen_dir})
  target_link_libraries(${ARG_TARGET} INTERFACE flatbuffers::flatbuffers)
  target_compile_definitions(${ARG_TARGET} INTERFACE
    CHATSIM_MSGS_BFBS="${bfbs}")
endfunction()
