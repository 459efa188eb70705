// BinningStage is a template in binning.h; this instance for the VGA width compiles it with
// core's warnings and in the float-free check (tests/CMakeLists.txt), whatever the users do.
#include "gradient/binning.h"

namespace qt {

template class BinningStage<640>;

}  // namespace qt
