// The browser's reader of decimal numbers for src/plan/options.cpp's read_number (every module of
// the web build links it with --js-library): JavaScript's Number() over `length` ASCII bytes that
// read_number has already checked are a decimal ([+-] digits [. digits] [e [+-] digits]). Number()
// rounds correctly to 20 significant digits, as strtod does natively; with it the C library's
// strtod and its long-double arithmetic stay out of the pages' modules (docs/payload.md).
mergeInto(LibraryManager.library, {
  penumbra_js_number: function (text, length) {
    return Number(String.fromCharCode.apply(null, HEAPU8.subarray(text, text + length)));
  },
});
