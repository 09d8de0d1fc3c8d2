vs.2.0
// tierlift helper (stencil outline): the object's vertices are already in clip space.
dcl_position v0

mov oPos, v0
