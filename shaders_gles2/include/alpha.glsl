// glTF alphaMode MASK (ALPHA_TEST): a fragment whose alpha (the base colour's times the base
// texture's, TEXTURED) is below u_alpha_cutoff is discarded, in the camera pass and in every pass
// that draws a caster (the shadow map's depth, the planar and Gooch stencil passes, Gooch's
// texture), so a cut-out casts a cut-out shadow. The texture is sampled as the camera pass samples
// it (bilinear, mipmapped where the image's size is a power of two); the ray-traced truth reads the
// base level bilinearly (scene::sample_alpha).
#if defined(ALPHA_TEST) || defined(ALPHA_BLEND)
uniform vec4 u_base_color;
#ifdef TEXTURED
uniform sampler2D u_base_texture;
#endif
float materialAlpha(vec2 uv) {
#ifdef TEXTURED
    return u_base_color.a * texture2D(u_base_texture, uv).a;
#else
    return u_base_color.a;
#endif
}
#endif
#ifdef ALPHA_TEST
uniform float u_alpha_cutoff;
#endif
