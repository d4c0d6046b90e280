// vtkLight's cone: inside it (angle to the axis at most the cone angle) the light falls off as
// cos(angle)^exponent, outside it gives nothing. l points from the surface to the light, the
// axis is the unit direction the light shines in.
float phongSpotlight(vec3 l, vec3 axis, float cosCone, float exponent)
{
  float c = dot(-l, axis);
  return c >= cosCone ? pow(c, exponent) : 0.0;
}
