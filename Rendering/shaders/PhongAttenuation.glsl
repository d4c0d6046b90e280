// vtkLight's attenuation of a positional light at distance d: 1 / (a0 + a1 d + a2 d^2).
float phongAttenuation(vec3 a, float d)
{
  return 1.0 / (a.x + (a.y + a.z * d) * d);
}
