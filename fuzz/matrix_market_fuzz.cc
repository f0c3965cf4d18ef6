// libFuzzer target for the .mtx readers, io::ReadMatrixMarket,
// io::ReadAbaqusCoordinateMatrix and io::ReadAbaqusLabelledMatrices (Abaqus's
// *MATRIX OUTPUT, FORMAT=COORDINATE and MATRIX INPUT): any input must
// give a matrix or a flexmb::Error, never a crash, hang or sanitizer report.
// A Matrix Market matrix that was read is written back ("general", so any
// matrix can be) and read again, and must come back bit for bit. Seeds:
// fuzz/corpus/matrix_market/.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe_io/abaqus/abaqus_matrix.h"
#include "flexmb/fe_io/matrix_market.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  flexmb::fuzz::ReadScratchFile(data, size, ".mtx", [](const std::string& path) {
    try {
      const flexmb::fe::SparseMat a = flexmb::io::ReadAbaqusCoordinateMatrix(path);
      if (a.rows() != a.cols()) std::abort();
    } catch (const flexmb::Error&) {
    }
    try {
      const flexmb::io::AbaqusLabelledMatrices l = flexmb::io::ReadAbaqusLabelledMatrices(path, path);
      if (l.K.rows() != static_cast<long>(l.dofs.size()) || l.M.rows() != l.K.rows()) std::abort();
    } catch (const flexmb::Error&) {
    }
    const flexmb::io::MatrixMarketMatrix m = flexmb::io::ReadMatrixMarket(path);
    if (m.A.nonZeros() > 20000) return;
    const std::string copy = path + ".copy.mtx";
    flexmb::io::MatrixMarketWriteOptions o;
    o.symmetric = false;
    flexmb::io::WriteMatrixMarket(m.A, copy, o);
    const flexmb::io::MatrixMarketMatrix back = flexmb::io::ReadMatrixMarket(copy);
    if (back.duplicates != 0 || !flexmb::fuzz::BitIdentical(m.A, back.A)) std::abort();
  });
  return 0;
}
