// A helper of its own, and none of the sheet's four functions.
float lightness(float shadow) {
    return 0.5 + 0.5 * shadow;
}
