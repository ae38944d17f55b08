// fuzz_rs274.cc: libFuzzer harness feeding arbitrary programs to the interpreter with a silent canon.
#include <cstddef>
#include <cstdint>
#include <string>

#include "emc/rs274ngc/interp.hh"
#include "emc/rs274ngc/sai_canon.hh"

// One input = one program; errors continue (like rs274 -n 0) within a line budget.
extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    std::string text(reinterpret_cast<const char *>(data), size);
    std::string line;
    SaiCanon canon(nullptr, &line);
    Interp in(canon);
    canon.set_line_source(&in.line_text());
    in.set_line_budget(20000);
    in.set_var_file("/nonexistent/fuzz.var");
    try {
        in.init();
    } catch (const InterpError &) {
        return 0;
    }
    in.open_text("fuzz.ngc", text);
    for (int errors = 0; errors < 200;) {
        InterpStatus st = in.execute_next();
        if (st == INTERP_EXIT) break;
        if (st != INTERP_ERROR) continue;
        errors++;
        if (in.at_end_of_file() || in.error_text() == "Line budget exhausted") break;
    }
    in.close();
    in.exit();
    return 0;
}
