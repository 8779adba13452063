// libFuzzer harness: bytes -> the YAML scene reader and its validation (parseScene).
// Every input must either give a Model or a sinew::SceneError; any other exception, a sanitizer
// report, a crash or a timeout is a finding. `mesh:` paths resolve against runs/ of the source
// tree, so the seeds from runs/*.yaml also read meshes/sail.msh. Built only with -DSINEW_FUZZ=ON
// (docs/robustness.md says how to run it).
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/scene_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const sinew::Model m = sinew::parseScene(text, SINEW_SOURCE_DIR "/runs");
    (void)m;
  } catch (const sinew::SceneError&) {
  }
  return 0;
}
