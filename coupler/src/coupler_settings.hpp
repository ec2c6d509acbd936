// The coupling.* fields of a case, read and checked in one place: by the
// coupler, and by `cosph-case plan` before the launcher starts any process.
#pragma once

#include "coupler_session.hpp"
#include "sphcore/case_file.hpp"

namespace cosph::coupler {

// A coupled case's coupler settings, all but the endpoint and the output
// folder (the command line's). Throws sph::ConfigError naming the file, the
// field and the reason for a bad coupling.* value.
CouplerSettings read_coupler_settings(const sph::CaseFile& case_file);

}  // namespace cosph::coupler
