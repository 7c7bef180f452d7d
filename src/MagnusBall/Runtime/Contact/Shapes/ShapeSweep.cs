// ShapeSweep: where a ball whose centre follows a cubic (one step's Hermite, in Bezier form) first touches a shape. A
// conservative bound (the control points' box, inflated by the radii) rules the shape out of a piece of the path, and the
// path is split in two where it cannot; where a piece is below LeafSizeM, its end is tested and the first touch refined by
// bisection. Pure geometry: the flight core (Flight/FlightStepper.Shapes.cs) gives it each step's ends.
using System;

namespace MagnusBall.Contact.Shapes
{
    /// <summary>The first touch of a ball sweeping along a cubic Bezier path with a shape.</summary>
    internal static class ShapeSweep
    {
        /// <summary>
        /// Pieces of the path whose bounding sphere is below this radius, m, are not split further: their end is tested. A pass that
        /// dips into a shape by less than about this within such a piece may be missed (0.1 micrometre).
        /// </summary>
        internal const double LeafSizeM = 1e-7;

        /// <summary>
        /// A touch counts only where the ball approaches the shape faster than this, m/s: a ball sliding along a surface it
        /// touches (its speed into it rounding's) is not hit again and again by rounding.
        /// </summary>
        internal const double MinApproachSpeed = 1e-9;

        /// <summary>
        /// The most pieces one search looks at. A path that stays too close to a surface for the bounds to rule out ends here; it is
        /// then scanned at <see cref="ScanSamples"/> even fractions instead, and a touch there refined by bisection.
        /// </summary>
        internal const int MaxVisits = 4096;

        /// <summary>How many even fractions of the path the scan after an exhausted search tests.</summary>
        internal const int ScanSamples = 256;

        /// <summary>True when the box [lo, hi] inflated by <paramref name="radius"/> meets the shape's bounding box.</summary>
        internal static bool MayTouch(ContactShape shape, in Vector3d lo, in Vector3d hi, double radius)
        {
            Vector3d min = shape.BoundsMin, max = shape.BoundsMax;
            return lo.X - radius <= max.X && hi.X + radius >= min.X &&
                lo.Y - radius <= max.Y && hi.Y + radius >= min.Y &&
                lo.Z - radius <= max.Z && hi.Z + radius >= min.Z;
        }

        /// <summary>
        /// The first fraction s in (0, 1] of the path B(s) (Bezier control points b0..b3) at which a ball of radius
        /// <paramref name="radius"/> touches <paramref name="shape"/> while approaching it (the centre's distance to the shape's
        /// surface reaches the radius, moving inward faster than <paramref name="minApproach"/> in path units per unit of s), to
        /// <paramref name="fractionTolerance"/>.
        /// </summary>
        internal static bool FirstContact(
            ContactShape shape, in Vector3d b0, in Vector3d b1, in Vector3d b2, in Vector3d b3, double radius, double fractionTolerance,
            double minApproach, out double fraction, out Vector3d normal, out int visits)
        {
            var search = new Search(shape, b0, b1, b2, b3, radius, fractionTolerance, minApproach);
            bool found = search.Visit(b0, b1, b2, b3, 0, 1) || (search.Exhausted && search.Scan());
            fraction = search.Fraction;
            normal = search.Normal;
            visits = search.Visits;
            return found;
        }

        /// <summary>The point of the Bezier path at <paramref name="s"/> (de Casteljau).</summary>
        internal static Vector3d PointAt(in Vector3d b0, in Vector3d b1, in Vector3d b2, in Vector3d b3, double s)
        {
            double r = 1 - s;
            Vector3d a = b0 * r + b1 * s, b = b1 * r + b2 * s, c = b2 * r + b3 * s;
            Vector3d d = a * r + b * s, e = b * r + c * s;
            return d * r + e * s;
        }

        /// <summary>The path's derivative dB/ds at <paramref name="s"/>.</summary>
        internal static Vector3d TangentAt(in Vector3d b0, in Vector3d b1, in Vector3d b2, in Vector3d b3, double s)
        {
            double r = 1 - s;
            return ((b1 - b0) * (r * r) + (b2 - b1) * (2 * r * s) + (b3 - b2) * (s * s)) * 3;
        }

        private struct Search
        {
            private readonly ContactShape _shape;
            private readonly Vector3d _b0, _b1, _b2, _b3;
            private readonly double _radius, _tolerance, _minApproach;
            private readonly bool _convex;
            public int Visits; // pieces looked at, and the scan's samples after an exhausted search
            public bool Exhausted;
            public double Fraction;
            public Vector3d Normal;

            public Search(ContactShape shape, in Vector3d b0, in Vector3d b1, in Vector3d b2, in Vector3d b3, double radius, double tolerance, double minApproach)
            {
                _minApproach = minApproach;
                _shape = shape;
                _convex = shape.IsConvex;
                _b0 = b0;
                _b1 = b1;
                _b2 = b2;
                _b3 = b3;
                _radius = radius;
                _tolerance = tolerance;
                Visits = 0;
                Exhausted = false;
                Fraction = 0;
                Normal = Vector3d.Zero;
            }

            // The piece [a, b] of the path, its own control points p0..p3: true, with Fraction and Normal, at its first touch.
            public bool Visit(in Vector3d p0, in Vector3d p1, in Vector3d p2, in Vector3d p3, double a, double b)
            {
                if (++Visits > MaxVisits)
                {
                    Exhausted = true;
                    return false;
                }

                Vector3d lo = new Vector3d(
                    Math.Min(Math.Min(p0.X, p1.X), Math.Min(p2.X, p3.X)),
                    Math.Min(Math.Min(p0.Y, p1.Y), Math.Min(p2.Y, p3.Y)),
                    Math.Min(Math.Min(p0.Z, p1.Z), Math.Min(p2.Z, p3.Z)));
                Vector3d hi = new Vector3d(
                    Math.Max(Math.Max(p0.X, p1.X), Math.Max(p2.X, p3.X)),
                    Math.Max(Math.Max(p0.Y, p1.Y), Math.Max(p2.Y, p3.Y)),
                    Math.Max(Math.Max(p0.Z, p1.Z), Math.Max(p2.Z, p3.Z)));
                // Every point of the piece is inside the control points' hull, so within `reach` of the box's centre; the
                // distance to the shape changes no faster than the point moves, so it is at least d(centre) - reach there.
                Vector3d centre = (lo + hi) * 0.5;
                double reach = (hi - lo).Length * 0.5;
                double distance = _shape.SignedDistance(centre, out Vector3d gradient);
                double margin = 1e-12 * (1 + centre.Length + reach); // rounding of the points and the distance
                double least = distance - reach;
                if (_convex && distance > 0)
                {
                    // A convex shape's distance is never below its tangent plane at a point outside it (where the normal is the
                    // distance's gradient; inside, on a capsule's or a cylinder's axis, the normal is rounding's direction), so on
                    // the piece (inside its control points' hull) it is at least its least value on the four points. A path that
                    // grazes a face is ruled out by how far it moves toward the face, not by how far it moves along it (with the
                    // slope alone, a ball skimming a table top could use up the search's MaxVisits before it came back down).
                    double tangent = distance + Math.Min(
                        Math.Min(Vector3d.Dot(gradient, p0 - centre), Vector3d.Dot(gradient, p1 - centre)),
                        Math.Min(Vector3d.Dot(gradient, p2 - centre), Vector3d.Dot(gradient, p3 - centre)));
                    least = Math.Max(least, tangent);
                }

                if (least - _radius > margin)
                {
                    return false;
                }

                if (reach <= LeafSizeM || b - a <= _tolerance)
                {
                    return Leaf(a, b);
                }

                // Split at the middle (de Casteljau).
                Vector3d l1 = (p0 + p1) * 0.5, m = (p1 + p2) * 0.5, r2 = (p2 + p3) * 0.5;
                Vector3d l2 = (l1 + m) * 0.5, r1 = (m + r2) * 0.5;
                Vector3d mid = (l2 + r1) * 0.5;
                double s = 0.5 * (a + b);
                return Visit(p0, l1, l2, mid, a, s) || Visit(mid, r1, r2, p3, s, b);
            }

            // A piece too small to split: the ball touches in it when it is in contact and approaching at its end; the first
            // such fraction is then refined by bisection (the piece is short enough that its distance is monotone in practice).
            private bool Leaf(double a, double b)
            {
                if (!Touching(b, out Vector3d normal))
                {
                    return false;
                }

                if (a > 0 || !Touching(a, out _))
                {
                    b = Refine(a, b, ref normal);
                }
                else
                {
                    b = a;
                    Touching(a, out normal);
                }

                Fraction = b;
                Normal = normal;
                return true;
            }

            // The path after an exhausted search: its first even fraction where the ball is touching and approaching, refined by
            // bisection from the fraction before it. A dip between two samples is missed (the search's bounds could not rule the
            // path out, so it runs within about their spacing of the surface).
            public bool Scan()
            {
                for (int k = 0; k <= ScanSamples; k++)
                {
                    double s = (double)k / ScanSamples;
                    Visits++;
                    if (Touching(s, out Vector3d normal))
                    {
                        Fraction = k == 0 ? 0 : Refine((double)(k - 1) / ScanSamples, s, ref normal);
                        Normal = normal;
                        return true;
                    }
                }

                return false;
            }

            // The first touching fraction in (lo, hi], where hi touches and lo does not, to the tolerance (bisection); its normal.
            private double Refine(double lo, double hi, ref Vector3d normal)
            {
                for (int i = 0; i < 64 && hi - lo > _tolerance; i++)
                {
                    double m = 0.5 * (lo + hi);
                    if (Touching(m, out Vector3d n))
                    {
                        hi = m;
                        normal = n;
                    }
                    else
                    {
                        lo = m;
                    }
                }

                return hi;
            }

            private bool Touching(double s, out Vector3d normal)
            {
                Vector3d p = PointAt(_b0, _b1, _b2, _b3, s);
                double gap = _shape.SignedDistance(p, out normal) - _radius;
                return gap <= 0 && Vector3d.Dot(TangentAt(_b0, _b1, _b2, _b3, s), normal) < -_minApproach;
            }
        }
    }
}
