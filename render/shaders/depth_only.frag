// The depth prepass of the main view (draw.c): lit.vert's positions with no shading,
// so the shaded pass after it runs lit.frag once per visible pixel. Nothing is written but
// depth (the colour buffers are off during the prepass).
layout(location = 0) out vec4 frag_color;

void main()
{
    frag_color = vec4(0.0);
}
