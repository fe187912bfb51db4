// The report without its in-page engine (a build without MOMENTA_WASM_ENGINE): its pages are
// recordings of one run, as before (docs/report.md).

namespace momenta::report::detail {
extern const char* const kEngineScript;
extern const char* const kEngineWasm;
const char* const kEngineScript = "";
const char* const kEngineWasm = "";
}  // namespace momenta::report::detail
