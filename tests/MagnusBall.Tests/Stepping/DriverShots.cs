using System;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Stepping;

namespace MagnusBall.Tests.Stepping
{
    /// <summary>Shots and frame-time sequences shared by the driver tests (Unity's y-up frame, x downrange).</summary>
    internal static class DriverShots
    {
        /// <summary>The Stepanek tennis model in a y-up frame.</summary>
        public static readonly FlightModel YUpTennis = Shots.StepanekTennis(Gravity.YUp);

        /// <summary>Up in the y-up frame.</summary>
        public static readonly Vector3d Up = Vector3d.UnitY;

        /// <summary>A launch from 1 m: speed (m/s), elevation and azimuth (deg, + toward +z), topspin and sidespin (rev/s).</summary>
        public static FlightState Launch(double speed, double elevationDegrees, double azimuthDegrees = 0, double topspinRps = 0, double sidespinRps = 0, double height = 1)
        {
            double e = elevationDegrees * Math.PI / 180, a = azimuthDegrees * Math.PI / 180;
            var velocity = new Vector3d(speed * Math.Cos(e) * Math.Cos(a), speed * Math.Sin(e), speed * Math.Cos(e) * Math.Sin(a));
            Vector3d spin = Vector3d.Zero;
            if (topspinRps != 0)
            {
                // Negative topspin is backspin.
                spin += Spin.Topspin(velocity, Up * Math.Sign(topspinRps), Spin.FromRevolutionsPerSecond(Math.Abs(topspinRps)));
            }

            if (sidespinRps != 0)
            {
                // Positive curls toward +z, negative toward -z.
                spin += Spin.Toward(velocity, Vector3d.UnitZ * Math.Sign(sidespinRps), Spin.FromRevolutionsPerSecond(Math.Abs(sidespinRps)));
            }

            return new FlightState(new Vector3d(0, height, 0), velocity, spin);
        }

        /// <summary>The 30 m/s drive with 20 rev/s topspin and a little sidespin.</summary>
        public static FlightState Drive => Launch(30, 8, 2, 20, 3);

        /// <summary>Frame deltas as Unity hands them out (single precision), for a fixed frame rate.</summary>
        public static double[] FixedRate(double framesPerSecond, int count)
        {
            var deltas = new double[count];
            for (int i = 0; i < count; i++)
            {
                deltas[i] = (float)(1.0 / framesPerSecond);
            }

            return deltas;
        }

        /// <summary>Random frame deltas in [5, 50] ms from a fixed seed.</summary>
        public static double[] Jittery(int seed, int count)
        {
            var random = new Random(seed);
            var deltas = new double[count];
            for (int i = 0; i < count; i++)
            {
                deltas[i] = (float)(0.005 + 0.045 * random.NextDouble());
            }

            return deltas;
        }

        /// <summary>60 FPS with one 0.5 s hitch at frame <paramref name="hitchFrame"/>.</summary>
        public static double[] WithHitch(int hitchFrame, int count)
        {
            double[] deltas = FixedRate(60, count);
            deltas[hitchFrame] = 0.5;
            return deltas;
        }

        /// <summary>
        /// Drives a flight through <paramref name="deltas"/> (repeating them if needed) until it lands and
        /// returns the landing event.
        /// </summary>
        public static FlightEvent LandWithDriver(FlightModel model, IIntegrator integrator, double step, FlightState start, double[] deltas)
        {
            var driver = new FixedStepDriver(model, integrator, step, start);
            Span<FlightEvent> events = stackalloc FlightEvent[8];
            for (int frame = 0; frame < 100_000; frame++)
            {
                AdvanceResult result = driver.Advance(deltas[frame % deltas.Length], events);
                for (int i = 0; i < result.EventCount; i++)
                {
                    if (events[i].Kind == FlightEventKinds.Landing)
                    {
                        return events[i];
                    }
                }
            }

            throw new InvalidOperationException("the ball did not land");
        }

        /// <summary>
        /// The thesis's stepping (Agrawal 2023, section 3.1.3): one integrator step per frame with the raw
        /// frame delta as the step, no accumulator and no clamp. The landing is located on the same cubic
        /// Hermite as the driver's, so only the stepping differs.
        /// </summary>
        public static Vector3d LandWithRawDeltas(FlightModel model, IIntegrator integrator, FlightState state, double[] deltas)
        {
            StateDerivative derivative = model.Derivative(state);
            for (int frame = 0; frame < 100_000; frame++)
            {
                double h = deltas[frame % deltas.Length];
                FlightState next = integrator.Step(model, state, derivative, h);
                StateDerivative nextDerivative = model.Derivative(next);
                if (next.Position.Y < 0)
                {
                    // One fixed "step" of exactly this frame's length, landing located by the driver's own rule.
                    var driver = new FixedStepDriver(model, integrator, h, state, maxFrameDeltaSeconds: h);
                    var events = new FlightEvent[4];
                    AdvanceResult result = driver.Advance(h, events);
                    for (int i = 0; i < result.EventCount; i++)
                    {
                        if (events[i].Kind == FlightEventKinds.Landing)
                        {
                            return events[i].Position;
                        }
                    }

                    throw new InvalidOperationException("the landing step did not report a landing");
                }

                state = next;
                derivative = nextDerivative;
            }

            throw new InvalidOperationException("the ball did not land");
        }
    }
}
