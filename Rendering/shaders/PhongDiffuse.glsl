// Diffuse term of one light: Id * max(n.l, 0), with n the unit surface normal and l the unit
// vector from the surface to the light. Nothing when the light is behind the surface.
vec3 phongDiffuse(vec3 n, vec3 l, vec3 Id)
{
  return Id * max(dot(n, l), 0.0);
}
