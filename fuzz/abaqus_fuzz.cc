// libFuzzer target for io::ReadAbaqus: any input must give a mesh or a
// flexmb::Error, never a crash, hang or sanitizer report. A mesh that was
// read is also written back and read again (the writer may refuse it with
// an InputError) and assembled, so that what the reader accepts is checked
// downstream too. Seeds: fuzz/corpus/abaqus/.

#include <cstddef>
#include <cstdint>
#include <string>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  flexmb::fuzz::SilenceWarnings();
  flexmb::fuzz::ReadScratchFile(data, size, ".inp", [](const std::string& path) {
    const flexmb::fe::Mesh mesh = flexmb::io::ReadAbaqus(path);
    if (mesh.nodes.size() > 2000 || mesh.elements.size() > 2000) return;
    flexmb::fuzz::ExpectCleanError([&] {
      const std::string copy = path + ".copy.inp";
      flexmb::io::WriteAbaqus(mesh, copy);
      flexmb::io::ReadAbaqus(copy);
    });
    flexmb::fe::Assemble(mesh);
  });
  return 0;
}
