using System;
using MagnusBall.Flight;
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
            Span<FlightEvent> events = stackalloc FlightEvent[8];
            for (int frame = 0; frame < 10_000 && !driver.IsFinished; frame++)
            {
                AdvanceResult result = driver.Advance(0.25, events);
                for (int i = 0; i < result.EventCount; i++)
                {
                    if (events[i].Kind == FlightEventKinds.Landing)
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
            var plain = new FixedStepDriver(TableTennis, RungeKutta4.Instance, fixedStep, Smash);
            Vector3d plainLanding = Land(plain);
            double plainError = plain.Diverged ? double.PositiveInfinity : Vector3d.Distance(plainLanding, reference);

            Assert.That(plainError, Is.GreaterThan(10 * error));
        }

        [Test]
        public void ADivergingStep_IsRefused_AndTheDriverKeepsItsLastGoodState()
        {
            // Forward Euler at a 0.25 s fixed step on that ball: h k C_D s = 3.5 at launch, far past Euler's limit of 2.
            var driver = new FixedStepDriver(TableTennisInSpace, ExplicitEuler.Instance, 0.25, Smash);
            FlightState lastGood = driver.State;
            AdvanceResult result = default;
            for (int frame = 0; frame < 100 && !result.Diverged; frame++)
            {
                lastGood = driver.State;
                result = driver.Advance(0.25);
            }

            Assert.That(result.Diverged, Is.True, "Euler at 3.5x its stability limit overflows");
            Assert.That(driver.Diverged, Is.True);
            Assert.That(driver.IsFinished, Is.True, "a refused step ends the flight");
            Assert.That(driver.State.IsFinite, Is.True);
            Assert.That(driver.State.Time, Is.EqualTo(lastGood.Time));
            Assert.That(driver.State.Position, Is.EqualTo(lastGood.Position));
        }

        [Test]
        public void ADivergingStep_LeavesTheDrawnBallRunningOnToTheLastGoodState()
        {
            // The render clock goes on by at most the frame time, never back, through the frame whose step is refused, and
            // the ball is then drawn at the last good state. Before, the refused step emptied the accumulator: the render
            // time fell back to the last step's start (a quarter of a second here) and the drawn ball jumped back a step.
            var driver = new FixedStepDriver(TableTennisInSpace, ExplicitEuler.Instance, 0.25, Smash);
            const double frame = 0.1;
            double last = driver.RenderTime;
            for (int i = 0; i < 200 && !(driver.Diverged && driver.RenderTime == driver.State.Time); i++)
            {
                driver.Advance(frame);
                double now = driver.RenderTime;
                // 1e-15 s: the rounding of the render time's sum (times below 10 s).
                Assert.That(now, Is.GreaterThanOrEqualTo(last - 1e-15), $"frame {i}: the render time went back (diverged: {driver.Diverged})");
                Assert.That(now - last, Is.LessThanOrEqualTo(frame + 1e-15), $"frame {i}: the render time jumped ahead");
                last = now;
            }

            Assert.That(driver.Diverged, Is.True);
            Assert.That(driver.RenderState.Position, Is.EqualTo(driver.State.Position), "drawn at the last good state");
            Assert.That(driver.Accumulator, Is.LessThanOrEqualTo(driver.FixedStep));
        }

        [Test]
        public void ADivergingBouncingStep_IsRefused_AndTheFlightIsLeftAsItWas()
        {
            // The court 1e300 m below: the run-away speed (squaring each step) overflows long before the ball gets there.
            var contact = new GroundContact(CrossBounce.Hard, new Plane(new Vector3d(0, 0, -1e300), Vector3d.UnitZ));
            var flight = new FlightStepper(TableTennisInSpace, ExplicitEuler.Instance, null, contact);
            flight.Reset(Smash);
            FlightState lastGood = flight.State;
            StepOutcome outcome = StepOutcome.Taken;
            for (int i = 0; i < 100 && outcome != StepOutcome.Diverged; i++)
            {
                lastGood = flight.State;
                outcome = flight.TryStep(0.25);
            }

            Assert.That(outcome, Is.EqualTo(StepOutcome.Diverged));
            Assert.That(flight.State, Is.EqualTo(lastGood));
            Assert.That(flight.Phase, Is.EqualTo(FlightPhase.Flying));
        }
    }
}
