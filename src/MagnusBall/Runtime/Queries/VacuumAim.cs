using System;

namespace MagnusBall.Queries
{
    /// <summary>
    /// The aim solver's first guesses: the closed forms of a ball under gravity alone (no air), in the launch frame (a
    /// horizontal path length and a rise along up, with g the length of the gravity vector, so nothing assumes an axis is
    /// up), and the slope of the height where the ball passes the target's distance with respect to the launch parameter,
    /// which starts the secant steps on the real flight.
    /// </summary>
    internal static class VacuumAim
    {
        /// <summary>
        /// The lower elevation (rad) at which a ball launched at <paramref name="speed"/> passes <paramref name="rise"/>
        /// above the launch point after a horizontal path of <paramref name="distance"/>; NaN when no elevation does it in a
        /// vacuum. <paramref name="slope"/>: d(height there)/d(elevation), m/rad (&gt;= 0 at the lower root).
        /// </summary>
        /// <remarks>
        /// With T = tan(elevation) and a = g x^2 / (2 v^2), the height at x is x T - a (1 + T^2); the lower root of
        /// a T^2 - x T + (a + rise) = 0 is T = 2 (a + rise) / (x + sqrt(x^2 - 4 a (a + rise))), written so that it does not
        /// cancel. The slope is (1 + T^2) (x - 2 a T) = (1 + T^2) sqrt(x^2 - 4 a (a + rise)).
        /// </remarks>
        public static double LowElevation(double gravity, double speed, double distance, double rise, out double slope)
        {
            slope = double.NaN;
            if (!Roots(gravity, speed, distance, rise, out double a, out double root))
            {
                return double.NaN;
            }

            double t = 2 * (a + rise) / (distance + root);
            slope = (1 + t * t) * root;
            return PortableMath.Atan(t);
        }

        /// <summary>
        /// The higher elevation (rad, the lob) at which a ball launched at <paramref name="speed"/> passes
        /// <paramref name="rise"/> above the launch point after a horizontal path of <paramref name="distance"/>; NaN when
        /// no elevation does it in a vacuum. <paramref name="slope"/>: d(height there)/d(elevation), m/rad (&lt;= 0 there).
        /// </summary>
        /// <remarks>The higher root of a T^2 - x T + (a + rise) = 0 (see <see cref="LowElevation"/>): T = (x + sqrt(D)) / (2 a);
        /// the slope is -(1 + T^2) sqrt(D).</remarks>
        public static double HighElevation(double gravity, double speed, double distance, double rise, out double slope)
        {
            slope = double.NaN;
            if (!Roots(gravity, speed, distance, rise, out double a, out double root) || !(a > 0))
            {
                return double.NaN;
            }

            double t = (distance + root) / (2 * a);
            slope = -(1 + t * t) * root;
            return double.IsFinite(slope) ? PortableMath.Atan(t) : double.NaN;
        }

        // The quadratic in T = tan(elevation) both elevations solve (LowElevation's remarks): its a = g x^2 / (2 v^2) and the
        // square root of its discriminant x^2 - 4 a (a + rise); false where the inputs or the discriminant rule out a real root.
        private static bool Roots(double gravity, double speed, double distance, double rise, out double a, out double root)
        {
            a = double.NaN;
            root = double.NaN;
            if (!(distance > 0) || !(speed > 0) || !(gravity > 0))
            {
                return false;
            }

            a = gravity * distance * distance / (2 * speed * speed);
            double discriminant = distance * distance - 4 * a * (a + rise);
            if (!(discriminant >= 0) || !double.IsFinite(discriminant))
            {
                return false;
            }

            root = Math.Sqrt(discriminant);
            return true;
        }

        /// <summary>
        /// The speed (m/s) at which a ball launched at <paramref name="elevation"/> passes <paramref name="rise"/> above the
        /// launch point after a horizontal path of <paramref name="distance"/>; NaN when none does (the line of the launch
        /// passes at or below the point). <paramref name="slope"/>: d(height there)/d(speed), m per m/s.
        /// </summary>
        /// <remarks>v^2 = g x^2 (1 + T^2) / (2 (x T - rise)); the height x T - g x^2 (1 + T^2) / (2 v^2) grows with v at
        /// g x^2 (1 + T^2) / v^3.</remarks>
        public static double Speed(double gravity, double elevation, double distance, double rise, out double slope)
        {
            slope = double.NaN;
            double c = PortableMath.Cos(elevation);
            if (!(distance > 0) || !(gravity > 0) || !(c > 0))
            {
                return double.NaN;
            }

            double t = PortableMath.Sin(elevation) / c;
            double above = distance * t - rise;
            if (!(above > 0))
            {
                return double.NaN;
            }

            double k = gravity * distance * distance * (1 + t * t);
            double v = Math.Sqrt(k / (2 * above));
            slope = k / (v * v * v);
            return double.IsFinite(v) ? v : double.NaN;
        }
    }
}
