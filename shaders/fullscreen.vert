#version 460
// One triangle covering the whole viewport, made from gl_VertexIndex (no vertex buffer):
// clip-space corners (-1,-1), (3,-1), (-1,3).
void main() {
    vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
