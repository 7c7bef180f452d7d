using System;
using System.Collections.Generic;
using MagnusBall.Flight;
using MagnusBall.Aerodynamics;
using MagnusBall.Contact;
using MagnusBall.Integration;
using MagnusBall.Queries;
using MagnusBall.Stepping;
using MagnusBall.Tests.Behavior;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>
    /// Multi-bounce flights under the frame adapter (Stepping.FixedStepDriver with a CrossBounce): the same bits
    /// whatever the frame rate, on every court, in z-up and Unity frames; and the same bounce points as
    /// BouncingFlight, an independent stepping of the same flight.
    /// </summary>
    [TestFixture]
    public class DriverBounceTests
    {
        private const double Step = 1.0 / 240;

        public static IEnumerable<TestCaseData> Cases()
        {
            foreach (Surface surface in Surface.Courts)
            {
                foreach (Court court in new[] { Court.ZUp, Court.Unity })
                {
                    yield return new TestCaseData(surface, court).SetArgDisplayNames(surface.Name, court.ToString());
                }
            }
        }

        private static FlightModel Model(Court court) =>
            new FlightModel(Ball.Tennis, new Air(1.21), court.Frame.Up * -Gravity.Standard, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));

        /// <summary>A 27 m/s drive with topspin and side spin (so the slip turns at the bounces), from 1 m.</summary>
        private static FlightState Drive(Court court)
        {
            Vector3d v = court.Frame.Map(26, 1.5, 6);
            Vector3d w = Spin.Topspin(v, court.Frame.Up, Spin.FromRpm(2400)) + Spin.Toward(v, court.Frame.Left, Spin.FromRpm(900));
            return new FlightState(court.Frame.Map(0, 0, 1), v, w);
        }

        /// <summary>The ground for the driver and for BouncingFlight: the ball touches when its centre is one radius up.</summary>
        private static Plane ContactHeight(Court court) => new Plane(court.Frame.Up * Ball.Tennis.Radius, court.Frame.Up);

        private static List<FlightEvent> Touches(Surface surface, Court court, double[] deltas)
        {
            FlightModel model = Model(court);
            var driver = new FixedStepDriver(model, RungeKutta4.Instance, Step, Drive(court),
                new FlightEventSet(court.Frame.Up, ContactHeight(court)), new CrossBounce(surface));
            var touches = new List<FlightEvent>();
            var events = new FlightEvent[16];
            for (int frame = 0; frame < 100_000 && !driver.IsFinished; frame++)
            {
                AdvanceResult result = driver.Advance(deltas[frame % deltas.Length], events);
                Assert.That(result.EventsNotReported, Is.EqualTo(0));
                for (int i = 0; i < result.EventCount; i++)
                {
                    if (events[i].Kind == FlightEventKinds.Bounce || events[i].Kind == FlightEventKinds.Landing)
                    {
                        touches.Add(events[i]);
                    }
                }
            }

            Assert.That(driver.IsFinished, Is.True, "the ball comes to rest");
            return touches;
        }

        [TestCaseSource(nameof(Cases))]
        public void MultiBounceFlight_UnderTheDriver_IsTheSameBits_AtEveryFrameRate(Surface surface, Court court)
        {
            List<FlightEvent> reference = Touches(surface, court, Stepping.DriverShots.FixedRate(60, 1));
            Assert.That(reference.Count, Is.GreaterThanOrEqualTo(3));
            foreach ((string name, double[] deltas) in new[]
            {
                ("30 FPS", Stepping.DriverShots.FixedRate(30, 60)),
                ("144 FPS", Stepping.DriverShots.FixedRate(144, 288)),
                ("jittery 5-50 ms", Stepping.DriverShots.Jittery(5, 400)),
                ("60 FPS, 0.5 s hitch", Stepping.DriverShots.WithHitch(30, 400)),
            })
            {
                List<FlightEvent> touches = Touches(surface, court, deltas);
                Assert.That(touches.Count, Is.EqualTo(reference.Count), name);
                for (int i = 0; i < touches.Count; i++)
                {
                    // Bitwise: exact equality, no tolerance.
                    Assert.That(touches[i].Time, Is.EqualTo(reference[i].Time), $"{name}, touch {i + 1}");
                    Assert.That(touches[i].Position, Is.EqualTo(reference[i].Position), $"{name}, touch {i + 1}");
                    Assert.That(touches[i].After.Velocity, Is.EqualTo(reference[i].After.Velocity), $"{name}, touch {i + 1}");
                    Assert.That(touches[i].After.AngularVelocity, Is.EqualTo(reference[i].After.AngularVelocity), $"{name}, touch {i + 1}");
                }
            }

            TestContext.Out.WriteLine($"{surface.Name}, {court}: {reference.Count} touches; first at {court.Forward(reference[0].Position):F4} m forward, " +
                $"{court.Left(reference[0].Position):F4} m left; second at {court.Forward(reference[1].Position):F4} m");
        }

        [TestCaseSource(nameof(Cases))]
        public void TheDriverAndBouncingFlight_BounceAtTheSamePoints(Surface surface, Court court)
        {
            // The driver steps a BouncingFlight of its own with the ball-centre ground one radius up; this one
            // bounces on the court plane directly. They agree to the integration error, not bit for bit.
            List<FlightEvent> driver = Touches(surface, court, Stepping.DriverShots.FixedRate(60, 1));
            FlightModel model = Model(court);
            var flight = Bouncing.Start(model, RungeKutta4.Instance, new CrossBounce(surface), new Plane(Vector3d.Zero, court.Frame.Up), Drive(court));
            var bounces = new List<FlightEvent>();
            Span<FlightEvent> buffer = stackalloc FlightEvent[4];
            for (int i = 0; i < 240 * 10 && bounces.Count < 3; i++)
            {
                int n = Bouncing.Step(flight, Step, buffer);
                for (int k = 0; k < n; k++)
                {
                    bounces.Add(buffer[k]);
                }
            }

            for (int i = 0; i < 3; i++)
            {
                double distance = Vector3d.Distance(driver[i].Position, bounces[i].Position);
                TestContext.Out.WriteLine($"{surface.Name}, {court}: bounce {i + 1} differs by {distance:E2} m, {Math.Abs(driver[i].Time - bounces[i].Time):E2} s");
                // RK4 at 1/240 s on two different step grids: each has a global error near 1e-11 m here (measured
                // differences up to 1.1e-11 m, 1e-12 s); a hundredfold margin.
                Assert.That(distance, Is.LessThan(1e-9), $"bounce {i + 1}");
                Assert.That(driver[i].Time, Is.EqualTo(bounces[i].Time).Within(1e-10), $"bounce {i + 1}");
            }
        }
    }
}
