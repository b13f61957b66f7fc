// A whole shader instead of the functions.
precision mediump float;
void main() {
    gl_FragColor = vec4(1.0);
}
