namespace MagnusBall.Stepping
{
    /// <summary>
    /// The cubic Hermite interpolant of one step from its two end states and derivatives (no extra
    /// derivative evaluation), and the crossing of a plane on it. Internal to the driver until the
    /// queries' dense output replaces it.
    /// </summary>
    internal static class CubicHermite
    {
        /// <summary>The state at fraction <paramref name="s"/> in [0, 1] of the step from a to b.</summary>
        internal static FlightState Interpolate(in FlightState a, in StateDerivative da, in FlightState b, in StateDerivative db, double s)
        {
            if (s <= 0)
            {
                return a;
            }

            if (s >= 1)
            {
                return b;
            }

            double h = b.Time - a.Time;
            double s2 = s * s, s3 = s2 * s;
            double h00 = 2 * s3 - 3 * s2 + 1;
            double h10 = (s3 - 2 * s2 + s) * h;
            double h01 = -2 * s3 + 3 * s2;
            double h11 = (s3 - s2) * h;
            return new FlightState(
                a.Position * h00 + da.Velocity * h10 + b.Position * h01 + db.Velocity * h11,
                a.Velocity * h00 + da.Acceleration * h10 + b.Velocity * h01 + db.Acceleration * h11,
                a.AngularVelocity * h00 + da.AngularAcceleration * h10 + b.AngularVelocity * h01 + db.AngularAcceleration * h11,
                a.Time + s * h);
        }

        /// <summary>
        /// The fraction of the step where the interpolated position crosses the plane, for a step whose ends
        /// are on opposite sides of it. Bisection to below 1e-15 of the step (a handful of cubic evaluations,
        /// no derivative evaluations).
        /// </summary>
        internal static double Crossing(
            in FlightState a, in StateDerivative da, in FlightState b, in StateDerivative db, in Vector3d point, in Vector3d normal, bool upward = false)
        {
            double h = b.Time - a.Time;

            // Signed distance along the normal is itself a cubic in s: f(s) = h00 f0 + h10 h f0' + h01 f1 + h11 h f1'.
            double f0 = Vector3d.Dot(a.Position - point, normal);
            double f1 = Vector3d.Dot(b.Position - point, normal);
            double m0 = Vector3d.Dot(da.Velocity, normal) * h;
            double m1 = Vector3d.Dot(db.Velocity, normal) * h;
            double lo = 0, hi = 1;
            bool startPositive = !upward;
            for (int i = 0; i < 60 && hi - lo > 1e-15; i++)
            {
                double s = 0.5 * (lo + hi);
                double s2 = s * s, s3 = s2 * s;
                double f = (2 * s3 - 3 * s2 + 1) * f0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * f1 + (s3 - s2) * m1;
                bool onStartSide = startPositive ? f >= 0 : f < 0;
                if (onStartSide)
                {
                    lo = s;
                }
                else
                {
                    hi = s;
                }
            }

            return hi;
        }
    }
}
