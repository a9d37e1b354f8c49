#pragma once
// The report writes its files through the floor's atomic output (runs/output_file.hpp).
#include "rotlie/runs/output_file.hpp"

namespace rotlie::reports {

using runs::printable_path;
using runs::remove_pending_temporaries;
using runs::remove_stale_temporaries;
using runs::temporary_prefix;
using runs::write_file_atomically;

}  // namespace rotlie::reports
