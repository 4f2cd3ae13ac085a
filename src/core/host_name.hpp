#pragma once
// The machine's name as facet writes it into files and their names: the
// temporaries beside an atomic write, the journal, the manifest's host.
#include <string>

namespace facet {

// This machine's name, with '/' and '.' made '_' so that it can sit inside
// a file name between dots (temporaries, journals); "unknown" when the
// system does not say.
std::string host_name();

}  // namespace facet
