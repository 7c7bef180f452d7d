using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Contact;
using MagnusBall.Integration;
using MagnusBall.Queries;
using MagnusBall.Stepping;
using NUnit.Framework;

namespace MagnusBall.Tests.Stepping
{
    /// <summary>The driver's default stepping is safe for light, fast balls; a diverging step is refused, not drawn.</summary>
    [TestFixture]
    public class DriverStabilityTests
    {
        // A table-tennis ball (2.7 g, 20 mm; C_D 0.5) in z-up air: its drag time scale at 100 m/s is 1/(k C_D s) = 72 ms.
        private static readonly FlightModel TableTennis = new FlightModel(
            new Ball(0.0027, 0.020, Ball.ThinShellInertiaFactor), new Air(1.2), Gravity.ZUp, new ConstantDrag(0.5), StepanekLift.Instance);

        // The same ball far from any ground (no gravity), so a run-away step overflows before anything is hit.
        private static readonly FlightModel TableTennisInSpace = TableTennis.WithGravity(Vector3d.Zero);

        private static FlightState Smash => new FlightState(new Vector3d(0, 0, 1), new Vector3d(99, 0, 14), new Vector3d(0, 300, 0));

        private static Vector3d Land(FixedStepDriver driver)
        {
            Span<FrameEvent> events = stackalloc FrameEvent[8];
            for (int frame = 0; frame < 10_000 && !driver.IsFinished; frame++)
            {
                AdvanceResult result = driver.Advance(0.25, events);
                for (int i = 0; i < result.EventCount; i++)
                {
                    if (events[i].Kind == FrameEventKind.Landing)
                    {
                        return events[i].Position;
                    }
                }
            }

            throw new InvalidOperationException("no landing");
        }

        [Test]
        public void TheShortConstructor_UsesStableRk4()
        {
            var driver = new FixedStepDriver(TableTennis, 1.0 / 240, Smash);
            Assert.That(driver.Integrator, Is.SameAs(StableIntegrator.RungeKutta4));
        }

        [TestCase(0.1)]
        [TestCase(0.25)]
        public void ALightBallAt100MetresPerSecond_WithAFixedStepOfAWholeHitch_StaysBoundedAndLandsNearTheReference(double fixedStep)
        {
            // The reference: RK4 at 1/4096 s (h k C_D s < 0.004 at launch), landing on the step's Hermite.
            Vector3d reference = Land(new FixedStepDriver(TableTennis, RungeKutta4.Instance, 1.0 / 4096, Smash));
            Vector3d safe = Land(new FixedStepDriver(TableTennis, fixedStep, Smash));
            double error = Vector3d.Distance(safe, reference);
            TestContext.Out.WriteLine($"step {fixedStep} s: default lands at {safe.X:F3} m, reference {reference.X:F3} m, error {error:E2} m");
            // 0.05 m on a 13 m range: the landing is then found on one cubic across a whole 0.1-0.25 s step (measured
            // 6-9 mm, the Hermite's interpolation error over so long a step); the plain method below is off by far more.
            Assert.That(error, Is.LessThan(0.05));

            // The plain RK4 at the same fixed step leaves the physical range: it runs away or lands nowhere near.
            double plainError;
            try
            {
                plainError = Vector3d.Distance(Land(new FixedStepDriver(TableTennis, RungeKutta4.Instance, fixedStep, Smash)), reference);
            }
            catch (InvalidOperationException)
            {
                plainError = double.PositiveInfinity;
            }

            Assert.That(plainError, Is.GreaterThan(10 * error));
        }

        [Test]
        public void ADivergingStep_IsRefused_AndTheDriverKeepsItsLastGoodState()
        {
            // Forward Euler at a 0.25 s fixed step on that ball: h k C_D s = 3.5 at launch, far past Euler's limit of 2.
            var driver = new FixedStepDriver(TableTennisInSpace, ExplicitEuler.Instance, 0.25, Smash);
            InvalidOperationException? error = null;
            FlightState lastGood = driver.State;
            for (int frame = 0; frame < 100 && error == null; frame++)
            {
                lastGood = driver.State;
                try
                {
                    driver.Advance(0.25);
                }
                catch (InvalidOperationException e)
                {
                    error = e;
                }
            }

            Assert.That(error, Is.Not.Null, "Euler at 3.5x its stability limit overflows");
            Assert.That(error!.Message, Does.Contain("StableIntegrator.RungeKutta4"));
            Assert.That(driver.State.IsFinite, Is.True);
            Assert.That(driver.State.Time, Is.EqualTo(lastGood.Time));
            Assert.That(driver.State.Position, Is.EqualTo(lastGood.Position));
        }

        [Test]
        public void ADivergingBouncingStep_IsRefused_AndTheFlightIsLeftAsItWas()
        {
            // The court 1e300 m below: the run-away speed (squaring each step) overflows long before the ball gets there.
            var flight = new BouncingFlight(TableTennisInSpace, ExplicitEuler.Instance, CrossBounce.Hard, new Plane(new Vector3d(0, 0, -1e300), Vector3d.UnitZ), Smash);
            Span<BounceEvent> bounces = stackalloc BounceEvent[BouncingFlight.MaxSegmentsPerStep];
            InvalidOperationException? error = null;
            FlightState lastGood = flight.State;
            for (int i = 0; i < 100 && error == null; i++)
            {
                lastGood = flight.State;
                try
                {
                    flight.Step(0.25, bounces);
                }
                catch (InvalidOperationException e)
                {
                    error = e;
                }
            }

            Assert.That(error, Is.Not.Null);
            Assert.That(flight.State.Position, Is.EqualTo(lastGood.Position));
            Assert.That(flight.State.Time, Is.EqualTo(lastGood.Time));
            Assert.That(flight.Phase, Is.EqualTo(FlightPhase.Flying));
        }
    }
}
