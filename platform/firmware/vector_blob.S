/* One file (golden vectors, a test frame) linked as bytes between the symbols
 * <QT_BLOB_SYMBOL>_begin and <QT_BLOB_SYMBOL>_end (not NUL-terminated). Assembled once per
 * file; CMakeLists.txt defines QT_BLOB_SYMBOL (an identifier), QT_BLOB_PATH (a quoted absolute
 * path) and optionally QT_BLOB_SECTION (default: read-only data in FLASH; the chain's frames
 * use .qt_frames.<name>, placed outside the flash budget by mps2.ld). */
#define QT_CAT_(a, b) a##b
#define QT_CAT(a, b) QT_CAT_(a, b)

#ifndef QT_BLOB_SECTION
#define QT_BLOB_SECTION .rodata.qt_vector_blob  /* one per object: --gc-sections still sees each */
#endif

    .section QT_BLOB_SECTION, "a", %progbits
    .p2align 2
    .global QT_CAT(QT_BLOB_SYMBOL, _begin)
    .global QT_CAT(QT_BLOB_SYMBOL, _end)
QT_CAT(QT_BLOB_SYMBOL, _begin):
    .incbin QT_BLOB_PATH
QT_CAT(QT_BLOB_SYMBOL, _end):
