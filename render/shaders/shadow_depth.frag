// The shadow pass writes depth only (render/src/shadow.c): no fragment work, so the
// rasteriser's early depth test does everything.
void main()
{
}
