// libFuzzer target for io::ReadNastran: any input must give a mesh or a
// flexmb::Error, never a crash, hang or sanitizer report. A mesh that was
// read is also assembled, so that what the reader accepts is checked
// downstream too. Seeds: fuzz/corpus/nastran/.

#include <cstddef>
#include <cstdint>
#include <string>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  flexmb::fuzz::SilenceWarnings();
  flexmb::fuzz::ReadScratchFile(data, size, ".bdf", [](const std::string& path) {
    const flexmb::fe::Mesh mesh = flexmb::io::ReadNastran(path);
    if (mesh.nodes.size() > 2000 || mesh.elements.size() > 2000) return;
    flexmb::fe::Assemble(mesh);
  });
  return 0;
}
