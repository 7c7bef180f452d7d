using System;
using MagnusBall.Integration;

namespace MagnusBall.Tests.Presets
{
    /// <summary>What a shot did: where it came down, how high it went and how steeply it landed.</summary>
    internal readonly struct ShotOutcome
    {
        public ShotOutcome(Vector3d landing, Vector3d landingVelocity, double apex, double time, double landingSpinRate)
        {
            Landing = landing;
            LandingVelocity = landingVelocity;
            Apex = apex;
            Time = time;
            LandingSpinRate = landingSpinRate;
        }

        /// <summary>Where the centre crossed the ground plane, m.</summary>
        public Vector3d Landing { get; }

        /// <summary>Velocity there, m/s.</summary>
        public Vector3d LandingVelocity { get; }

        /// <summary>Highest height above the ground, m.</summary>
        public double Apex { get; }

        /// <summary>Flight time, s.</summary>
        public double Time { get; }

        /// <summary>|w| at landing, rad/s.</summary>
        public double LandingSpinRate { get; }
    }

    /// <summary>
    /// A small local flight loop for the preset tests: classic RK4 at a fixed 1 ms step (error far below the
    /// tolerances used: the step is 1/1000 of every flight here), stopped where the centre's height above the
    /// ground plane through the origin changes sign, the crossing interpolated linearly inside the last step
    /// (position error ~ |a| h^2 / 8 ~ 1e-6 m).
    /// </summary>
    internal static class ShotFlight
    {
        public const double Step = 1e-3;

        /// <summary>A launch state: speed, elevation above the horizontal, horizontal heading, from a height, with a spin vector.</summary>
        public static FlightState Launch(Vector3d up, Vector3d downrange, double height, double speed, double elevationDegrees, Func<Vector3d, Vector3d> spin)
        {
            double e = elevationDegrees * Math.PI / 180;
            Vector3d velocity = downrange * (speed * Math.Cos(e)) + up * (speed * Math.Sin(e));
            return new FlightState(up * height, velocity, spin(velocity));
        }

        /// <summary>Flies until the centre crosses the ground plane (height 0 along up) on the way down.</summary>
        public static ShotOutcome Fly(FlightModel model, FlightState state, double maxTime = 30)
        {
            Vector3d up = model.Up;
            IIntegrator rk4 = RungeKutta4.Instance;
            StateDerivative derivative = model.Derivative(state);
            double apex = Vector3d.Dot(state.Position, up);
            while (state.Time < maxTime)
            {
                FlightState next = rk4.Step(model, state, derivative, Step);
                double h0 = Vector3d.Dot(state.Position, up);
                double h1 = Vector3d.Dot(next.Position, up);
                apex = Math.Max(apex, h1);
                if (h0 >= 0 && h1 < 0)
                {
                    double t = h0 / (h0 - h1);
                    return new ShotOutcome(
                        Vector3d.Lerp(state.Position, next.Position, t),
                        Vector3d.Lerp(state.Velocity, next.Velocity, t),
                        apex,
                        state.Time + t * Step,
                        next.AngularVelocity.Length);
                }

                state = next;
                derivative = model.Derivative(state);
            }

            throw new InvalidOperationException("the ball did not land within maxTime");
        }

        /// <summary>Landing angle below the horizontal, degrees.</summary>
        public static double LandingAngleDegrees(in ShotOutcome outcome, Vector3d up)
        {
            double vertical = -Vector3d.Dot(outcome.LandingVelocity, up);
            double horizontal = (outcome.LandingVelocity + up * vertical).Length;
            return Math.Atan2(vertical, horizontal) * 180 / Math.PI;
        }

        public const double MetresPerYard = 0.9144;
        public const double MetresPerFoot = 0.3048;
        public const double MetresPerSecondPerMph = 0.44704;
    }
}
