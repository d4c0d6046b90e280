// Specular term of one light: Is * max(v.r, 0)^alpha with r = 2(l.n)n - l the mirror direction
// of l, v the unit vector from the surface to the eye. Nothing when the light is behind the
// surface (n.l <= 0), and nothing when v.r <= 0 (pow(0, alpha) is undefined in GLSL).
vec3 phongSpecular(vec3 n, vec3 l, vec3 v, vec3 Is, float alpha)
{
  float nl = dot(n, l);
  if (nl <= 0.0)
  {
    return vec3(0.0);
  }
  float vr = dot(v, 2.0 * nl * n - l);
  return vr > 0.0 ? Is * pow(vr, alpha) : vec3(0.0);
}
