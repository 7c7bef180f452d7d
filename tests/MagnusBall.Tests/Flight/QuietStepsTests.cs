using System;
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

        [TestCase(0)]
        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(4)]
        [TestCase(5)]
        public void ADivergingStep_InARun_IsRefused_AfterTheQuietSteps_AndTheirPreviousStateKept(int offset)
        {
            // A spin decaying with a 1 s time constant, stepped 20 s at a time: far beyond RK4's stability limit, each step
            // multiplies the spin by R(-20) = 1 - 20 + 200 - 1333.3 + 6666.7 = 5514, so from 1e270 rad/s it overflows after
            // ten finite steps (no drag or lift: the ball itself flies on). The run starts `offset` steps before the first
            // step that diverges, so the refused step comes after a different number of quiet steps each time (none, one from
            // the current state, and each of the three slots).
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

        // FixedStepDriver.Advance as it was before TrySteps (9eb1398): one TryStep call a step, the caps and the deferral tested
        // before each. The reference the driver is held to, frame by frame.
        private sealed class OneTryStepPerStep
        {
            private readonly FlightStepper _stepper;
            private readonly double _step;
            private readonly int _maxSteps;
            private readonly FlightEventKinds _stopAt;
            private double _accumulator;
            private bool _diverged;

            public OneTryStepPerStep(FixedStepDriver driver, FlightState start, FlightEventSet events, IBounceModel? bounce)
            {
                GroundContact? contact = null;
                if (bounce != null)
                {
                    Plane ground = events.Ground!.Value;
                    contact = new GroundContact(bounce, new Plane(ground.Point - ground.Normal * driver.Model.Ball.Radius, ground.Normal));
                }

                _stepper = new FlightStepper(driver.Model, driver.Integrator, events, contact);
                _stepper.Reset(start);
                _step = driver.FixedStep;
                _maxSteps = driver.MaxStepsPerAdvance;
                _stopAt = contact == null ? FlightEventKinds.Landing : FlightEventKinds.None;
            }

            public FlightStepper Stepper => _stepper;

            public double Accumulator => _accumulator;

            public AdvanceResult Advance(double delta, Span<FlightEvent> events)
            {
                double dropped = 0;
                if (delta > FixedStepDriver.DefaultMaxFrameDeltaSeconds)
                {
                    dropped = delta - FixedStepDriver.DefaultMaxFrameDeltaSeconds;
                    delta = FixedStepDriver.DefaultMaxFrameDeltaSeconds;
                }

                if (_stepper.IsStopped || _diverged)
                {
                    _accumulator = Math.Min(_accumulator + delta, _step);
                    return new AdvanceResult(0, 0, 0, dropped + delta, _diverged);
                }

                _accumulator += delta;
                int steps = 0, written = 0, lost = 0;
                int perStep = _stepper.MaximumEventsPerStep;
                bool deferrable = events.Length >= perStep, deferred = false;
                long workBefore = _stepper.DerivativeEvaluations + _stepper.StepCount;
                while (_accumulator >= _step)
                {
                    if (steps == _maxSteps || _stepper.DerivativeEvaluations + _stepper.StepCount - workBefore >= FixedStepDriver.MaxEvaluationsPerAdvance)
                    {
                        double keep = _accumulator % _step;
                        dropped += _accumulator - keep;
                        _accumulator = keep;
                        break;
                    }

                    if (deferrable && events.Length - written < perStep)
                    {
                        deferred = true;
                        break;
                    }

                    double stepStart = _stepper.CurrentTime;
                    StepOutcome outcome = _stepper.TryStep(_step, _stopAt);
                    if (outcome == StepOutcome.Diverged || outcome == StepOutcome.TimeCannotAdvance)
                    {
                        _diverged = true;
                        dropped += _accumulator - _step;
                        _accumulator = _step;
                        break;
                    }

                    steps++;
                    _accumulator -= _stepper.IsStopped ? _stepper.CurrentTime - stepStart : _step;
                    foreach (FlightEvent e in _stepper.Events.ToArray())
                    {
                        if (written < events.Length)
                        {
                            events[written++] = e;
                        }
                        else
                        {
                            lost++;
                        }
                    }

                    if (_stepper.IsStopped)
                    {
                        break;
                    }
                }

                return new AdvanceResult(steps, written, lost, dropped, _diverged, deferred);
            }
        }

        [TestCase("rk4", false, 0, 1.0 / 240)]
        [TestCase("stable-rk4", false, 3, 1.0 / 240)]
        [TestCase("stable-rk4", true, 0, 1.0 / 240)]
        [TestCase("rk4", false, 0, 1.0 / 1000)]
        [TestCase("heun", false, 5, 1.0 / 240)]
        [TestCase("dp54", true, 0, 1.0 / 240)]
        [TestCase("rk4", false, 0, 1e-6)]
        public void TheDriver_IsTheLoopOfOneTryStepAStep_FrameByFrame(string integratorName, bool bounces, int maxStepsPerAdvance, double step)
        {
            // Frames of every length (zero, jittery, hitches past the clamp), event buffers of every size about the most one
            // step can write (so steps are deferred and events lost), step caps, and at 1e-6 s the work cap (250,000 steps a
            // 0.25 s frame, 50,000 allowed; a plane 0.5 m out is crossed in the first frame, so the driver's runs of steps do
            // not line up with the cap): after each frame the driver and the old loop agree on everything, bit for bit.
            IIntegrator integrator = Integrators.FromName(integratorName);
            FlightModel model = Shots.StepanekTennis(Gravity.ZUp);
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            var near = new Plane(new Vector3d(0.5, 0, 0), Vector3d.UnitX);
            FlightEventSet events = FlightEventSet.ForModel(model, net, near);
            FlightState start = Shots.ZUpDrive(new Vector3d(0, 150, 0), speed: 25, elevationDegrees: 12);
            IBounceModel? bounce = bounces ? CrossBounce.Hard : null;
            var driver = new FixedStepDriver(model, integrator, step, start, events, bounce, maxStepsPerAdvance: maxStepsPerAdvance);
            var old = new OneTryStepPerStep(driver, start, events, bounce);
            int per = driver.MaximumEventsPerStep;
            int[] sizes = { 0, 1, per - 1, per, per + 1, 4 * per };
            var random = new Random(5);
            int frames = 0, deferredFrames = 0, capped = 0;
            int limit = step < 1e-4 ? 4 : 1500;
            while (!driver.IsFinished && frames < limit)
            {
                int roll = random.Next(10);
                double delta = step < 1e-4 ? 0.25 : roll == 0 ? 0.3 : roll == 1 ? 0 : random.NextDouble() * 0.05;
                int size = sizes[random.Next(sizes.Length)];
                var mine = new FlightEvent[size];
                var theirs = new FlightEvent[size];
                AdvanceResult got = driver.Advance(delta, mine);
                AdvanceResult expected = old.Advance(delta, theirs);
                frames++;
                string when = $"frame {frames} (delta {delta}, buffer {size})";
                Assert.That(got.StepsTaken, Is.EqualTo(expected.StepsTaken), when + ": steps");
                Assert.That(got.EventCount, Is.EqualTo(expected.EventCount), when + ": events");
                Assert.That(got.EventsNotReported, Is.EqualTo(expected.EventsNotReported), when + ": events lost");
                Assert.That(got.StepsDeferred, Is.EqualTo(expected.StepsDeferred), when + ": deferred");
                Assert.That(got.Diverged, Is.EqualTo(expected.Diverged), when + ": diverged");
                Assert.That(BitConverter.DoubleToInt64Bits(got.DroppedSeconds), Is.EqualTo(BitConverter.DoubleToInt64Bits(expected.DroppedSeconds)), when + ": dropped");
                Assert.That(BitConverter.DoubleToInt64Bits(driver.Accumulator), Is.EqualTo(BitConverter.DoubleToInt64Bits(old.Accumulator)), when + ": accumulator");
                Assert.That(mine, Is.EqualTo(theirs), when + ": the events written");
                Assert.That(driver.State, Is.EqualTo(old.Stepper.State), when + ": state");
                Assert.That(driver.PreviousState, Is.EqualTo(old.Stepper.PreviousState), when + ": previous state");
                Assert.That(driver.TotalSteps, Is.EqualTo(old.Stepper.StepCount), when + ": steps in all");
                Assert.That(driver.DerivativeEvaluations, Is.EqualTo(old.Stepper.DerivativeEvaluations), when + ": evaluations");
                deferredFrames += got.StepsDeferred ? 1 : 0;
                capped += got.DroppedSeconds > 0 && delta <= FixedStepDriver.DefaultMaxFrameDeltaSeconds ? 1 : 0;
            }

            Assert.That(step < 1e-4 ? capped == frames : driver.IsFinished, Is.True,
                step < 1e-4 ? "every 0.25 s frame at 1e-6 s meets the work cap" : "the flight ends");
            if (step >= 1e-4 && !bounces && maxStepsPerAdvance == 0)
            {
                Assert.That(deferredFrames, Is.GreaterThan(0), "some frames defer steps for a short buffer");
            }
        }

        [Test]
        public void AUserLawThatThrows_MidFrame_LeavesTheDriverConsistent()
        {
            // A user's drag law that fails for a while in the middle of the flight: the call throws, and the driver keeps a state
            // the steps it counts reach, and an accumulator that holds the rest of the time it was given (the steps of the stepper
            // call that threw are not kept, and their time stays in the accumulator).
            var drag = new SwitchableDrag();
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, drag, StepanekLift.Instance);
            var working = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, new SwitchableDrag(), StepanekLift.Instance);
            FlightState start = Shots.ZUpDrive(new Vector3d(0, 150, 0), speed: 25, elevationDegrees: 12);
            const double step = 1.0 / 256, frame = 1.0 / 64; // binary fractions: the accumulator's sums are exact
            var driver = new FixedStepDriver(model, RungeKutta4.Instance, step, start);
            double given = 0;
            int threw = 0;
            for (int i = 0; i < 40; i++)
            {
                drag.Throw = i >= 10 && i < 13;
                try
                {
                    driver.Advance(frame);
                }
                catch (InvalidOperationException)
                {
                    threw++;
                }

                given += frame;
                var reference = new FlightStepper(working, RungeKutta4.Instance, FlightEventSet.ForModel(working));
                reference.Reset(start);
                for (long k = 0; k < driver.TotalSteps; k++)
                {
                    reference.TryStep(step, FlightEventKinds.Landing);
                }

                Assert.That(driver.State, Is.EqualTo(reference.State), $"frame {i}: the state is that of the steps it counts");
                Assert.That(driver.TotalSteps * step + driver.Accumulator, Is.EqualTo(given), $"frame {i}: no time lost or counted twice");
            }

            Assert.That(threw, Is.EqualTo(3));
            Assert.That(driver.TotalSteps, Is.EqualTo(160), "the time held over is stepped once the law works again");
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
