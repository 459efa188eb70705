/* One file (golden vectors, a scene frame, its expected text) linked into flash as bytes,
 * between the symbols <QT_BLOB_SYMBOL>_begin and <QT_BLOB_SYMBOL>_end (not NUL-terminated).
 * Assembled once per file; CMakeLists.txt defines QT_BLOB_SYMBOL (an identifier) and
 * QT_BLOB_PATH (a quoted absolute path) for each. */
#define QT_CAT_(a, b) a##b
#define QT_CAT(a, b) QT_CAT_(a, b)

    .section .rodata.qt_vector_blob, "a", %progbits  /* one per object: --gc-sections still sees each */
    .p2align 2
    .global QT_CAT(QT_BLOB_SYMBOL, _begin)
    .global QT_CAT(QT_BLOB_SYMBOL, _end)
QT_CAT(QT_BLOB_SYMBOL, _begin):
    .incbin QT_BLOB_PATH
QT_CAT(QT_BLOB_SYMBOL, _end):
