using System;

namespace MagnusBall.Cli
{
    /// <summary>
    /// Dense output and event location inside one step, for the CLI. TEMPORARY: this is a stand-in until the
    /// library's Queries API (src/MagnusBall/Queries) is on main; the CLI calls only these three methods so
    /// that the switch is one file. It uses the same method the issue asks of the library: a cubic Hermite
    /// between the step's end states and derivatives (no extra evaluation) and a bracketed root to 1e-12 s.
    /// </summary>
    internal static class StepEvents
    {
        private const double TimeTolerance = 1e-12;

        /// <summary>The state at time <paramref name="time"/> in [s0.Time, s1.Time] on the cubic Hermite.</summary>
        public static FlightState Interpolate(in FlightState s0, in StateDerivative d0, in FlightState s1, in StateDerivative d1, double time)
        {
            double h = s1.Time - s0.Time;
            double u = h > 0 ? Math.Clamp((time - s0.Time) / h, 0, 1) : 1;
            return new FlightState(
                Hermite(s0.Position, d0.Velocity, s1.Position, d1.Velocity, h, u),
                Hermite(s0.Velocity, d0.Acceleration, s1.Velocity, d1.Acceleration, h, u),
                Hermite(s0.AngularVelocity, d0.AngularAcceleration, s1.AngularVelocity, d1.AngularAcceleration, h, u),
                s0.Time + u * h);
        }

        /// <summary>
        /// The first time in the step where the signed distance n.(p - q) goes from &lt; 0 to &gt;= 0
        /// (<paramref name="along"/> true) or from &gt; 0 to &lt;= 0 (false), judged at the step's ends.
        /// </summary>
        public static bool TryPlaneCrossing(
            in FlightState s0, in StateDerivative d0, in FlightState s1, in StateDerivative d1,
            Vector3d point, Vector3d normal, bool along, out FlightState at)
        {
            double sign = along ? 1 : -1;
            double f0 = sign * Vector3d.Dot(s0.Position - point, normal);
            double f1 = sign * Vector3d.Dot(s1.Position - point, normal);
            if (!(f0 < 0 && f1 >= 0))
            {
                at = default;
                return false;
            }

            at = Root(s0, d0, s1, d1, state => sign * Vector3d.Dot(state.Position - point, normal));
            return true;
        }

        /// <summary>The time in the step where the velocity along <paramref name="up"/> goes from &gt; 0 to &lt;= 0.</summary>
        public static bool TryApex(in FlightState s0, in StateDerivative d0, in FlightState s1, in StateDerivative d1, Vector3d up, out FlightState at)
        {
            double f0 = Vector3d.Dot(s0.Velocity, up);
            double f1 = Vector3d.Dot(s1.Velocity, up);
            if (!(f0 > 0 && f1 <= 0))
            {
                at = default;
                return false;
            }

            at = Root(s0, d0, s1, d1, state => -Vector3d.Dot(state.Velocity, up));
            return true;
        }

        // Bisection on the interpolant: f < 0 at s0, f >= 0 at s1.
        private static FlightState Root(in FlightState s0, in StateDerivative d0, in FlightState s1, in StateDerivative d1, Func<FlightState, double> f)
        {
            double lo = s0.Time, hi = s1.Time;
            while (hi - lo > TimeTolerance)
            {
                double mid = 0.5 * (lo + hi);
                if (mid <= lo || mid >= hi)
                {
                    break;
                }

                if (f(Interpolate(s0, d0, s1, d1, mid)) < 0)
                {
                    lo = mid;
                }
                else
                {
                    hi = mid;
                }
            }

            return Interpolate(s0, d0, s1, d1, hi);
        }

        private static Vector3d Hermite(in Vector3d y0, in Vector3d dy0, in Vector3d y1, in Vector3d dy1, double h, double u)
        {
            double u2 = u * u, u3 = u2 * u;
            double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
            return y0 * h00 + dy0 * (h10 * h) + y1 * h01 + dy1 * (h11 * h);
        }
    }
}
