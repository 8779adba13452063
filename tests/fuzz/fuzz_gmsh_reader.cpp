// libFuzzer harness: bytes -> the Gmsh 4 ASCII reader (parseGmsh). Every input must either give
// a mesh or a sinew::SceneError. Built only with -DSINEW_FUZZ=ON (docs/robustness.md).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "scene/gmsh_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const sinew::GmshMesh mesh = sinew::parseGmsh(in, "fuzz.msh");
    (void)mesh;
  } catch (const sinew::SceneError&) {
  }
  return 0;
}
