// Compares my_faces (dcel_adapter.hpp) with the reference DCEL on graphs made
// from the fuzzer's bytes; a difference aborts with the graph and the report.
#include "dcel/testing/fuzz_solver.hpp"
#include "dcel_adapter.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return dcel::testing::fuzz_faces_solver(data, size, my_faces);
}
