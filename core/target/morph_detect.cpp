// morph_detect.h is a template. This instantiates the QVGA window so that the library build
// (-Werror -Wconversion ...) and the float-free check compile every line of it.
#include "target/morph_detect.h"

namespace qt {

template class MorphDetector<84, 84>;

}  // namespace qt
