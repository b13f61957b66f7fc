# Dependencies of the browser build (Emscripten, preset "web").
#
# Emscripten's sysroot does not see /usr/include, and adding /usr/include itself to a wasm build
# would pull the host's libc headers in. The header-only libraries the web build uses (only glm:
# the exercise pages need no glTF, JSON or image code) are reached through a folder that holds
# nothing but symlinks to them, made here at configure time.
set(PENUMBRA_WEB_INCLUDE ${CMAKE_BINARY_DIR}/deps/include)
file(MAKE_DIRECTORY ${PENUMBRA_WEB_INCLUDE})
foreach(dep glm)
  if(NOT EXISTS /usr/include/${dep})
    message(FATAL_ERROR "/usr/include/${dep} is missing: install libglm-dev (scripts/setup.sh does)")
  endif()
  file(CREATE_LINK /usr/include/${dep} ${PENUMBRA_WEB_INCLUDE}/${dep} SYMBOLIC)
endforeach()
add_library(glm::glm INTERFACE IMPORTED)
set_target_properties(glm::glm PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${PENUMBRA_WEB_INCLUDE})
# glm's headers are not ours: no warnings from them.
set_target_properties(glm::glm PROPERTIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES ${PENUMBRA_WEB_INCLUDE})

# The library throws gl::Error on any GL failure (a lost context among them) and the pages catch
# it: Emscripten's exception catching is off unless asked for, in every translation unit.
# The pages' module and its libraries add -fwasm-exceptions (web/CMakeLists.txt: WebAssembly's own
# exceptions, no JavaScript invoke_* wrappers), which takes precedence over this.
add_compile_options(-fexceptions)
add_link_options(-fexceptions)
