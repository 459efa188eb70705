// harris.h is all templates. This instantiates the QVGA configuration so that the library
// build (-Werror -Wconversion ...) and the float-free check compile every line of it.
#include "target/harris.h"

namespace qt {

template class HarrisDetector<320, 96, 4, 2>;
template Status detect_features<320, 96, 4, 2>(HarrisDetector<320, 96, 4, 2>&, const uint8_t*,
                                               uint16_t, uint16_t, uint32_t, const HarrisParams&,
                                               FeatureSet<4, 96>&);

}  // namespace qt
