// libFuzzer target for the texsplat-raw header parser: any input either parses or throws
// texsplat::Error (never crashes, hangs or trips a sanitizer), and a header that parses must
// format to text that parses back to the same header.

#include "nodes/volume/RawHeader.h"
#include "scenegraph/Error.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace {

[[noreturn]] void fail(const std::string& what, const std::string& text) {
    std::fprintf(stderr, "%s:\n%s\n", what.c_str(), text.c_str());
    std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using texsplat::volume::RawHeader;
    RawHeader header;
    try {
        std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
        header = RawHeader::parse(in, "fuzz.raw");
        header.dataBytes();
    } catch (const texsplat::Error&) {
        return 0;
    }
    const std::string formatted = header.format();
    std::istringstream again(formatted);
    RawHeader reread;
    try {
        reread = RawHeader::parse(again, "formatted.raw");
    } catch (const texsplat::Error& error) {
        fail(std::string("formatted header does not parse back: ") + error.what(), formatted);
    }
    if (reread.format() != formatted || reread.dims != header.dims ||
        reread.spacing != header.spacing || reread.origin != header.origin) {
        fail("round trip changed the header", formatted + "---\n" + reread.format());
    }
    return 0;
}
