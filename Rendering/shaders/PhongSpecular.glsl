// Specular term of one light: Is * max(v.r, 0)^alpha with r = 2(l.n)n - l the mirror direction
// of l, v the unit vector from the surface to the eye. Nothing when the light is behind the
// surface (n.l <= 0) or v.r <= 0. A select rather than a branch (a branch costs llvmpipe both
// sides and the mask); pow's argument is kept positive (pow(0, alpha) is undefined in GLSL).
vec3 phongSpecular(vec3 n, vec3 l, vec3 v, vec3 Is, float alpha)
{
  float nl = dot(n, l);
  float vr = dot(v, 2.0 * nl * n - l);
  float s = pow(max(vr, 1.0e-30), alpha);
  return (nl > 0.0 && vr > 0.0) ? s * Is : vec3(0.0);
}
