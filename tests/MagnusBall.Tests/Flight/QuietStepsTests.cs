using System;
using System.Collections.Generic;
using MagnusBall.Aerodynamics;
using MagnusBall.Contact;
using MagnusBall.Integration;
using MagnusBall.Stepping;
using NUnit.Framework;

namespace MagnusBall.Tests.Flight
{
    using MagnusBall.Flight;

    /// <summary>
    /// <c>FlightStepper.TrySteps</c>, the driver's frame in one call: its quiet steps pass their states on in locals and are
    /// committed once, and the first step that is not quiet is taken as <c>TryStep</c> takes it. Each test flies the same
    /// ball both ways and asserts the same flight bit for bit: state, derivative, previous state, the last step's dense output,
    /// the counters (the evaluations against the model's real calls), the phase and the events.
    /// </summary>
    [TestFixture]
    public class QuietStepsTests
    {
        private const double Step = 1.0 / 240;

        // A model of its own for each stepper, so that each counts its own calls.
        private static FlightModel Counted(FlightModel model, out EvaluationCount calls)
        {
            calls = new EvaluationCount();
            model.CountedEvaluations = calls;
            return model;
        }

        private static FlightStepper Stepper(FlightModel model, IIntegrator integrator, bool bounces)
        {
            // The ground, the apex and a plane across the flight, so that quiet runs are cut by events at many places.
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            FlightEventSet events = FlightEventSet.ForModel(model, net);
            GroundContact? contact = bounces ? new GroundContact(CrossBounce.Hard, Plane.Ground(model)) : null;
            return new FlightStepper(model, integrator, events, contact);
        }

        [TestCase("rk4", 2, false)]
        [TestCase("rk4", 3, false)]
        [TestCase("rk4", 4, false)]
        [TestCase("rk4", 7, false)]
        [TestCase("stable-rk4", 4, false)]
        [TestCase("stable-rk4", 5, true)]
        [TestCase("rk4", 6, true)]
        [TestCase("heun", 4, false)]
        [TestCase("dp54", 3, true)]
        public void TrySteps_IsTryStepCalls_BitForBit(string integratorName, int count, bool bounces)
        {
            // A topspin drive from 1 m: it rises to its apex, crosses the net plane, then lands (the flight stops there) or
            // bounces and rolls (with a contact, where every step after the first bounce goes the general way). Methods other
            // than RK4 have no quiet steps: TrySteps then takes one step a call.
            IIntegrator integrator = Integrators.FromName(integratorName);
            FlightModel together = Counted(Shots.StepanekTennis(Gravity.ZUp), out EvaluationCount togetherCalls);
            FlightModel apart = Counted(Shots.StepanekTennis(Gravity.ZUp), out EvaluationCount apartCalls);
            FlightStepper t = Stepper(together, integrator, bounces);
            FlightStepper r = Stepper(apart, integrator, bounces);
            FlightState start = Shots.ZUpDrive(new Vector3d(0, 150, 0), speed: 25, elevationDegrees: 12);
            t.Reset(start);
            r.Reset(start);
            FlightEventKinds stopAt = bounces ? FlightEventKinds.None : FlightEventKinds.Landing;
            int calls = 0, cutShort = 0, events = 0;
            while (!t.IsStopped && calls < 2000)
            {
                StepOutcome outcome = t.TrySteps(Step, stopAt, count, out int quiet, out double lastStart);
                calls++;
                for (int i = 0; i < quiet; i++)
                {
                    double before = r.CurrentTime;
                    Assert.That(r.TryStep(Step, stopAt), Is.EqualTo(StepOutcome.Taken), $"call {calls}: a quiet step is a taken step");
                    Assert.That(r.Events.Length, Is.Zero, $"call {calls}: a quiet step has no event");
                    if (i == quiet - 1 && quiet == count)
                    {
                        Assert.That(lastStart, Is.EqualTo(before), "the last step's start");
                    }
                }

                if (quiet < count)
                {
                    cutShort++;
                    double before = r.CurrentTime;
                    Assert.That(outcome, Is.EqualTo(r.TryStep(Step, stopAt)), $"call {calls}: the step after the quiet ones");
                    Assert.That(lastStart, Is.EqualTo(before), "the last step's start");
                    events += r.Events.Length;
                }
                else
                {
                    Assert.That(outcome, Is.EqualTo(StepOutcome.Taken));
                }

                AssertSameFlight(t, r, $"after call {calls}");
            }

            Assert.That(bounces ? t.BounceCount > 0 && t.Phase != FlightPhase.Flying : t.IsStopped, Is.True, "it lands, or bounces and rolls");
            Assert.That(cutShort, Is.GreaterThan(integratorName.EndsWith("rk4") ? 0 : calls - 1), "steps that are not quiet cut the runs");
            Assert.That(events, Is.GreaterThanOrEqualTo(3), "the apex, the net plane and the landing at least");
            Assert.That(t.DerivativeEvaluations, Is.EqualTo(togetherCalls.Calls), "the counter counts the real calls");
            Assert.That(togetherCalls.Calls, Is.EqualTo(apartCalls.Calls), "no evaluation made twice or saved");
        }

        [TestCase(2)]
        [TestCase(3)]
        [TestCase(4)]
        [TestCase(5)]
        public void ADivergingStep_InARun_IsRefused_AfterTheQuietSteps_AndTheirPreviousStateKept(int offset)
        {
            // A spin decaying with a 1 s time constant, stepped 20 s at a time: far beyond RK4's stability limit, each step
            // multiplies the spin by R(-20) = 1 - 20 + 200 - 1333.3 + 6666.7 = 5514, so from 1e270 rad/s it overflows after
            // ten finite steps (no drag or lift: the ball itself flies on). The run starts `offset` steps before the first
            // step that diverges, so the refused step comes after a different number of quiet steps each time, in each of the
            // three slots.
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Vector3d.Zero, null, null, new ExponentialSpinDecay(1));
            var start = new FlightState(new Vector3d(0, 0, 100), new Vector3d(10, 0, 0), new Vector3d(0, 0, 1e270));
            const double step = 20;
            var probe = new FlightStepper(model, RungeKutta4.Instance);
            probe.Reset(start);
            int finite = 0;
            while (probe.TryStep(step) == StepOutcome.Taken && finite < 50)
            {
                finite++;
            }

            Assert.That(finite, Is.EqualTo(10), "ten finite steps, then the spin overflows");
            var t = new FlightStepper(model, RungeKutta4.Instance);
            var r = new FlightStepper(model, RungeKutta4.Instance);
            t.Reset(start);
            r.Reset(start);
            for (int i = 0; i < finite - offset; i++)
            {
                Assert.That(t.TryStep(step), Is.EqualTo(StepOutcome.Taken));
                Assert.That(r.TryStep(step), Is.EqualTo(StepOutcome.Taken));
            }

            Assert.That(t.TrySteps(step, FlightEventKinds.None, 10, out int quiet, out double lastStart), Is.EqualTo(StepOutcome.Diverged));
            Assert.That(quiet, Is.EqualTo(offset), "the steps before the diverging one are taken");
            for (int i = 0; i < offset; i++)
            {
                Assert.That(r.TryStep(step), Is.EqualTo(StepOutcome.Taken));
            }

            Assert.That(lastStart, Is.EqualTo(r.CurrentTime), "the refused step starts where the quiet ones end");
            Assert.That(r.TryStep(step), Is.EqualTo(StepOutcome.Diverged));
            AssertSameFlight(t, r, "after the refused step");
        }

        [Test]
        public void AClockThatCannotAdvance_InARun_IsRefused_AfterTheQuietSteps()
        {
            // From t = 2^53 - 2 s with 1 s steps the clock reads 2^53 - 1, then 2^53, and then cannot advance (2^53 + 1 rounds to
            // 2^53): two quiet steps, then TimeCannotAdvance, with nothing of the third step kept.
            FlightModel model = FlightModel.Vacuum(Ball.Tennis, Gravity.ZUp);
            var start = new FlightState(new Vector3d(0, 0, 1e9), new Vector3d(10, 0, 0), default, 9007199254740990.0);
            var t = new FlightStepper(model, RungeKutta4.Instance);
            var r = new FlightStepper(model, RungeKutta4.Instance);
            t.Reset(start);
            r.Reset(start);
            Assert.That(t.TrySteps(1.0, FlightEventKinds.None, 4, out int quiet, out double lastStart), Is.EqualTo(StepOutcome.TimeCannotAdvance));
            Assert.That(quiet, Is.EqualTo(2));
            Assert.That(lastStart, Is.EqualTo(9007199254740992.0));
            Assert.That(r.TryStep(1.0), Is.EqualTo(StepOutcome.Taken));
            Assert.That(r.TryStep(1.0), Is.EqualTo(StepOutcome.Taken));
            Assert.That(r.TryStep(1.0), Is.EqualTo(StepOutcome.TimeCannotAdvance));
            AssertSameFlight(t, r, "after the refused step");
        }

        [TestCase("stable-rk4", 3)]
        [TestCase("rk4", 1)]
        [TestCase("rk4", 4)]
        [TestCase("heun", 2)]
        public void TheDriver_TakesTheStepsOfOneTryStepEach(string integratorName, int maxStepsPerAdvance)
        {
            // Frames of every length (jittery, with hitches past the clamp) under a step cap, through the apex, the net plane
            // and the landing: after each frame the driver's stepper is a stepper that took the frame's steps one TryStep call at
            // a time, and the frame reported that stepper's events.
            IIntegrator integrator = Integrators.FromName(integratorName);
            FlightModel model = Shots.StepanekTennis(Gravity.ZUp);
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            FlightEventSet events = FlightEventSet.ForModel(model, net);
            FlightState start = Shots.ZUpDrive(new Vector3d(0, 150, 0), speed: 25, elevationDegrees: 12);
            var driver = new FixedStepDriver(model, integrator, Step, start, events, maxStepsPerAdvance: maxStepsPerAdvance);
            var r = new FlightStepper(model, integrator, events);
            r.Reset(start);
            var random = new Random(11);
            var buffer = new FlightEvent[64];
            var expected = new List<FlightEvent>();
            int frames = 0, reported = 0;
            while (!driver.IsFinished && frames < 3000)
            {
                double delta = random.Next(10) == 0 ? 0.3 : random.NextDouble() * 0.05;
                AdvanceResult result = driver.Advance(delta, buffer);
                frames++;
                expected.Clear();
                for (int i = 0; i < result.StepsTaken; i++)
                {
                    Assert.That(r.TryStep(Step, FlightEventKinds.Landing), Is.EqualTo(StepOutcome.Taken).Or.EqualTo(StepOutcome.Stopped));
                    expected.AddRange(r.Events.ToArray());
                }

                Assert.That(result.StepsTaken, Is.LessThanOrEqualTo(driver.MaxStepsPerAdvance));
                Assert.That(result.EventCount, Is.EqualTo(expected.Count), $"frame {frames}");
                for (int i = 0; i < expected.Count; i++)
                {
                    Assert.That(buffer[i], Is.EqualTo(expected[i]), $"frame {frames}, event {i}");
                }

                reported += result.EventCount;
                Assert.That(driver.State, Is.EqualTo(r.State), $"frame {frames}");
                Assert.That(driver.PreviousState, Is.EqualTo(r.PreviousState), $"frame {frames}");
                Assert.That(driver.TotalSteps, Is.EqualTo(r.StepCount), $"frame {frames}");
                Assert.That(driver.DerivativeEvaluations, Is.EqualTo(r.DerivativeEvaluations), $"frame {frames}");
            }

            Assert.That(driver.IsFinished && r.IsStopped, Is.True, "both land");
            Assert.That(reported, Is.GreaterThanOrEqualTo(3), "the apex, the net plane and the landing");
        }

        // The same flight, bit for bit (FlightState and StateDerivative compare their doubles' bits: value-type equality).
        private static void AssertSameFlight(FlightStepper t, FlightStepper r, string when)
        {
            Assert.That(t.State, Is.EqualTo(r.State), when + ": state");
            Assert.That(t.Derivative, Is.EqualTo(r.Derivative), when + ": derivative");
            Assert.That(t.PreviousState, Is.EqualTo(r.PreviousState), when + ": previous state");
            Assert.That(t.StepCount, Is.EqualTo(r.StepCount), when + ": steps");
            Assert.That(t.DerivativeEvaluations, Is.EqualTo(r.DerivativeEvaluations), when + ": evaluations");
            Assert.That(t.Phase, Is.EqualTo(r.Phase), when + ": phase");
            Assert.That(t.BounceCount, Is.EqualTo(r.BounceCount), when + ": bounces");
            Assert.That(t.Events.ToArray(), Is.EqualTo(r.Events.ToArray()), when + ": events");
            HermiteSegment ts = t.LastSegment, rs = r.LastSegment;
            Assert.That(ts.Start, Is.EqualTo(rs.Start), when + ": the last step's dense output");
            Assert.That(ts.StartDerivative, Is.EqualTo(rs.StartDerivative), when + ": the last step's dense output");
            Assert.That(ts.End, Is.EqualTo(rs.End), when + ": the last step's dense output");
            Assert.That(ts.EndDerivative, Is.EqualTo(rs.EndDerivative), when + ": the last step's dense output");
        }
    }
}
