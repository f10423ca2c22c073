# Common settings for every tfd target: repository root on the include path, warnings on.
function(tfd_target_defaults target)
  target_include_directories(${target} PUBLIC ${PROJECT_SOURCE_DIR})
  target_compile_options(${target} PRIVATE -Wall -Wextra)
  # GCC 12's -Wrestrict fires falsely inside libstdc++ on `"literal" + std::string`
  # (GCC bug 105329, fixed in GCC 13): silence it there only.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
endfunction()

# One library per layer, made of every .cpp below the layer's folder.
function(tfd_layer_library target folder)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${folder}/*.cpp)
  add_library(${target} STATIC ${sources})
  tfd_target_defaults(${target})
endfunction()
