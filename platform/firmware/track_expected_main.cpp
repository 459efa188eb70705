// A host program, built and run by platform/firmware/CMakeLists.txt, writing the checksums of
// track_sequence.h, computed on the build machine, as track_expected.h for track_bench.
#include <stdio.h>

#include "track_sequence.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: track_expected_host OUTPUT.h\n");
        return 2;
    }
    unsigned long sums[qt::kTrackCaseCount];
    for (int i = 0; i < qt::kTrackCaseCount; ++i) sums[i] = qt::track_checksum(qt::kTrackCases[i]);
    FILE* f = fopen(argv[1], "w");
    if (f == NULL) {
        perror(argv[1]);
        return 1;
    }
    fprintf(f,
            "// Generated at build time by track_expected_host: the checksums of\n"
            "// track_sequence.h computed on the build machine.\n#define QT_TRACK_EXPECTED {");
    for (int i = 0; i < qt::kTrackCaseCount; ++i)
        fprintf(f, "{\"%s\", 0x%08lxu}, ", qt::kTrackCases[i].name, sums[i]);
    fprintf(f, "}\n");
    return fclose(f) == 0 ? 0 : 1;
}
