using System;
using System.Collections.Generic;
using MagnusBall.Flight;
using MagnusBall.Contact;
using MagnusBall.Integration;
using MagnusBall.Queries;
using MagnusBall.Stepping;
using NUnit.Framework;

namespace MagnusBall.Tests.Stepping
{
    /// <summary>The accumulator, the clamp, the substep cap, interpolation, events and bad input.</summary>
    [TestFixture]
    public class FixedStepDriverTests
    {
        // Binary fractions, so the accumulator arithmetic below is exact and step counts are certain.
        private const double Step = 1.0 / 256;

        private static FixedStepDriver NewDriver(FlightState? start = null, Plane[]? planes = null, double clamp = 0.25, int maxSteps = 0, IBounceModel? bounce = null) =>
            new FixedStepDriver(
                DriverShots.YUpTennis, RungeKutta4.Instance, Step, start ?? DriverShots.Drive,
                new FlightEventSet(DriverShots.Up, Plane.Ground(DriverShots.YUpTennis), planes), bounce, clamp, maxSteps);

        [Test]
        public void Advance_TakesWholeStepsAndKeepsTheRemainder()
        {
            FixedStepDriver driver = NewDriver();
            AdvanceResult result = driver.Advance(4.5 * Step);
            Assert.That(result.StepsTaken, Is.EqualTo(4));
            Assert.That(driver.Accumulator, Is.EqualTo(0.5 * Step));
            Assert.That(driver.Alpha, Is.EqualTo(0.5));
            Assert.That(driver.State.Time, Is.EqualTo(4 * Step));
            Assert.That(driver.PreviousState.Time, Is.EqualTo(3 * Step));
            Assert.That(driver.RenderTime, Is.EqualTo(3.5 * Step));

            result = driver.Advance(0.25 * Step);
            Assert.That(result.StepsTaken, Is.EqualTo(0));
            result = driver.Advance(0.25 * Step);
            Assert.That(result.StepsTaken, Is.EqualTo(1));
            Assert.That(driver.Accumulator, Is.EqualTo(0));
            Assert.That(driver.TotalSteps, Is.EqualTo(5));
        }

        [Test]
        public void TheSameSteps_AsAPlainFixedStepLoop()
        {
            FixedStepDriver driver = NewDriver();
            driver.Advance(0.125); // 32 steps
            FlightState plain = Shots.Fly(DriverShots.YUpTennis, RungeKutta4.Instance, DriverShots.Drive, Step, 32);
            Assert.That(driver.State.Position, Is.EqualTo(plain.Position));
            Assert.That(driver.State.Velocity, Is.EqualTo(plain.Velocity));
        }

        [Test]
        public void AHitch_IsClampedAndTheRestDropped()
        {
            FixedStepDriver driver = NewDriver();
            AdvanceResult result = driver.Advance(1.0);
            Assert.That(result.StepsTaken, Is.EqualTo(64), "0.25 s clamp / (1/256 s)");
            Assert.That(result.DroppedSeconds, Is.EqualTo(0.75));
            Assert.That(driver.State.Time, Is.EqualTo(0.25));

            FixedStepDriver custom = NewDriver(clamp: 0.0625);
            Assert.That(custom.Advance(0.5).StepsTaken, Is.EqualTo(16));
        }

        [Test]
        public void TheSubstepCap_LimitsStepsPerFrame_AndKeepsAlphaBelowOne()
        {
            FixedStepDriver driver = NewDriver(maxSteps: 5);
            AdvanceResult result = driver.Advance(10.5 * Step);
            Assert.That(result.StepsTaken, Is.EqualTo(5));
            Assert.That(result.DroppedSeconds, Is.EqualTo(5 * Step));
            Assert.That(driver.Accumulator, Is.EqualTo(0.5 * Step));
            Assert.That(driver.MaxStepsPerAdvance, Is.EqualTo(5));
            Assert.That(NewDriver().MaxStepsPerAdvance, Is.EqualTo(65), "ceil(0.25 * 256) + 1: the clamp binds first");
        }

        [Test]
        public void RenderState_IsExactForTheVacuumParabola()
        {
            // A cubic Hermite reproduces a quadratic exactly, and RK4 steps the parabola exactly, so the render
            // state between steps is the closed form to round-off.
            FlightModel vacuum = FlightModel.Vacuum(Ball.Tennis, Gravity.YUp);
            var start = new FlightState(new Vector3d(0, 1, 0), new Vector3d(20, 8, -3), Vector3d.Zero);
            var driver = new FixedStepDriver(vacuum, RungeKutta4.Instance, Step, start);
            driver.Advance(10.25 * Step);
            FlightState render = driver.RenderState;
            double t = 9.25 * Step;
            Vector3d expected = start.Position + start.Velocity * t + Gravity.YUp * (0.5 * t * t);
            Assert.That(render.Time, Is.EqualTo(t));
            // 1e-13 m: round-off of a few dozen operations on numbers of order 1 m.
            Assert.That(Vector3d.Distance(render.Position, expected), Is.LessThan(1e-13));
            Assert.That(Vector3d.Distance(render.Velocity, start.Velocity + Gravity.YUp * t), Is.LessThan(1e-13));
        }

        [Test]
        public void RenderState_MovesSmoothlyFromFrameToFrame()
        {
            // At 144 FPS (1.78 steps a frame) the render time advances by exactly the frame time every frame
            // once the first step is taken (the render runs one step behind the simulation), so the drawn ball
            // neither repeats a position nor jumps a whole step.
            FixedStepDriver driver = NewDriver();
            double frame = 1.0 / 144;
            driver.Advance(frame);
            Vector3d last = driver.RenderState.Position;
            double lastTime = driver.RenderTime;
            for (int i = 0; i < 60; i++)
            {
                driver.Advance(frame);
                // 1e-15 s: round-off of the accumulator's additions and subtractions.
                Assert.That(driver.RenderTime - lastTime, Is.EqualTo(frame).Within(1e-15), $"frame {i}");
                Vector3d now = driver.RenderState.Position;
                double speed = driver.RenderState.Velocity.Length;
                // Within 2 % of speed * frame time: speed changes by far less than that over one frame here.
                Assert.That(Vector3d.Distance(now, last), Is.EqualTo(speed * frame).Within(0.02 * speed * frame), $"frame {i}");
                last = now;
                lastTime = driver.RenderTime;
            }
        }

        [Test]
        public void RenderState_MovesOnThroughTheLandingFrame_AndStaysInTheLastStep()
        {
            // The landing step is cut short. The drawn ball must keep moving by its speed times the frame time until it
            // reaches the landing, through the frame that takes the landing step: before, the driver took a whole step's time
            // out of the accumulator for it, the render clock lost the cut part, and the ball stood nearly still for a frame
            // (0.01 of a frame's travel here). And the render time stays inside the last step (to rounding), so no older
            // piece of flight is needed to draw it. Frames of 1/1000 s, a quarter of a step; frame rates 30-240 FPS too.
            foreach (double frame in new[] { 1.0 / 1000, 1.0 / 240, 1.0 / 144, 1.0 / 60, 1.0 / 30 })
            {
                FixedStepDriver driver = NewDriver();
                Vector3d last = driver.RenderState.Position;
                double lastTime = driver.RenderTime;
                int frames = 0;
                for (int i = 0; i < 5000 && !(driver.IsFinished && driver.RenderState.Position == driver.State.Position); i++)
                {
                    driver.Advance(frame);
                    FlightState render = driver.RenderState;
                    // 1e-15 s: the rounding of the render time's sum.
                    Assert.That(render.Time, Is.GreaterThanOrEqualTo(driver.PreviousState.Time - 1e-15), $"frame {i} at {frame} s: before the last step");
                    double speed = render.Velocity.Length;
                    double moved = Vector3d.Distance(render.Position, last);
                    // A frame's travel to 3 % (speed changes by less than that over a frame, up to 1/30 s here); the frames
                    // before the render clock starts (it runs a step behind) and the frame that reaches the landing (clamped
                    // to it) move less.
                    Assert.That(moved, Is.LessThanOrEqualTo(1.03 * speed * frame), $"frame {i} at {frame} s: the drawn ball jumped");
                    if (lastTime > 0 && render.Time < driver.State.Time)
                    {
                        Assert.That(moved, Is.GreaterThanOrEqualTo(0.97 * speed * frame), $"frame {i} at {frame} s: the drawn ball slowed (finished: {driver.IsFinished})");
                        Assert.That(render.Time - lastTime, Is.EqualTo(frame).Within(1e-15), $"frame {i} at {frame} s: the render clock");
                        frames++;
                    }

                    last = render.Position;
                    lastTime = render.Time;
                }

                Assert.That(driver.IsFinished, Is.True);
                Assert.That(driver.RenderState.Position, Is.EqualTo(driver.State.Position), "it comes to rest at the landing");
                Assert.That(frames, Is.GreaterThan(20));
            }
        }

        [Test]
        public void Landing_IsReportedOnce_OnTheGround_AndEndsTheFlight()
        {
            FixedStepDriver driver = NewDriver();
            var events = new FlightEvent[4];
            var landings = new List<FlightEvent>();
            for (int i = 0; i < 200; i++)
            {
                AdvanceResult result = driver.Advance(1.0 / 60, events);
                for (int e = 0; e < result.EventCount; e++)
                {
                    if (events[e].Kind != FlightEventKinds.Apex)
                    {
                        landings.Add(events[e]);
                    }
                }
            }

            Assert.That(landings, Has.Count.EqualTo(1));
            FlightEvent landing = landings[0];
            Assert.That(landing.Kind, Is.EqualTo(FlightEventKinds.Landing));
            Assert.That(landing.PlaneIndex, Is.EqualTo(-1));
            // 1e-12 m: the crossing is bisected to 1e-15 of a step, where the ball moves about 0.1 m.
            Assert.That(landing.Position.Y, Is.EqualTo(0).Within(1e-12));
            Assert.That(driver.IsFinished, Is.True);
            Assert.That(driver.State.Position, Is.EqualTo(landing.Position));
            Assert.That(driver.RenderState.Position, Is.EqualTo(landing.Position), "the render state comes to rest at the landing");
            Assert.That(driver.Advance(0.1).StepsTaken, Is.EqualTo(0));
        }

        [Test]
        public void Landing_KeepsTheIntegratorsOrder()
        {
            // RK4 at 1/64 s against RK4 at 1/8192 s: the located landing (not the step below ground) agrees
            // to 1e-5 m, the accuracy issue 3 asks of event location at 1/60 s.
            FlightEvent coarse = DriverShots.LandWithDriver(DriverShots.YUpTennis, RungeKutta4.Instance, 1.0 / 64, DriverShots.Drive, DriverShots.FixedRate(60, 1));
            FlightEvent fine = DriverShots.LandWithDriver(DriverShots.YUpTennis, RungeKutta4.Instance, 1.0 / 8192, DriverShots.Drive, DriverShots.FixedRate(60, 1));
            TestContext.Out.WriteLine($"landing 1/64 s: {coarse.Position}, 1/8192 s: {fine.Position}, difference {Vector3d.Distance(coarse.Position, fine.Position):G3} m");
            Assert.That(Vector3d.Distance(coarse.Position, fine.Position), Is.LessThan(1e-5));
        }

        [Test]
        public void PlaneCrossings_AreReportedInTimeOrder_BeforeTheLanding()
        {
            Plane[] planes =
            {
                new Plane(new Vector3d(18, 0, 0), Vector3d.UnitX),      // a line far up the court
                new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX),  // the net
                new Plane(new Vector3d(40, 0, 0), Vector3d.UnitX),      // beyond the landing: never reported
                new Plane(new Vector3d(5, 0, 0), -Vector3d.UnitX),      // crossed against its normal: not reported
            };
            FixedStepDriver driver = NewDriver(planes: planes);
            Span<FlightEvent> events = stackalloc FlightEvent[8];
            // One long frame holding the whole flight, so the ordering is within one buffer.
            var reported = new List<FlightEvent>();
            for (int i = 0; i < 8 && !driver.IsFinished; i++)
            {
                AdvanceResult result = driver.Advance(0.25, events);
                for (int e = 0; e < result.EventCount; e++)
                {
                    reported.Add(events[e]);
                }
            }

            FlightEvent apex = reported.Find(e => e.Kind == FlightEventKinds.Apex);
            // 1e-9 m/s: the apex is located to 1e-12 s, where the vertical speed changes by 1e-11 m/s.
            Assert.That(apex.State.Velocity.Y, Is.EqualTo(0).Within(1e-9));
            reported.RemoveAll(e => e.Kind == FlightEventKinds.Apex);
            Assert.That(reported.ConvertAll(e => e.PlaneIndex), Is.EqualTo(new[] { 1, 0, -1 }));
            Assert.That(reported[2].Kind, Is.EqualTo(FlightEventKinds.Landing));
            // 1e-12 m: bisection to 1e-15 of a step.
            Assert.That(reported[0].Position.X, Is.EqualTo(11.885).Within(1e-12));
            Assert.That(reported[1].Position.X, Is.EqualTo(18).Within(1e-12));
            Assert.That(reported[0].Time, Is.LessThan(reported[1].Time));
            Assert.That(reported[1].Time, Is.LessThan(reported[2].Time));
        }

        [Test]
        public void EventsThatDoNotFit_AreCounted()
        {
            FixedStepDriver driver = NewDriver(planes: new[] { new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX) });
            int lost = 0;
            for (int i = 0; i < 8; i++)
            {
                AdvanceResult result = driver.Advance(0.25);
                Assert.That(result.EventCount, Is.EqualTo(0));
                lost += result.EventsNotReported;
            }

            Assert.That(lost, Is.EqualTo(3), "the apex, the net crossing and the landing");
        }

        [TestCase(false)]
        [TestCase(true)]
        public void AWholeFlight_AllocatesNothing(bool bouncing)
        {
            var planes = new[] { new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX) };
            var events = new FlightEvent[4];
            double[] deltas = DriverShots.Jittery(7, 64);
            FixedStepDriver driver = NewDriver(planes: planes, bounce: bouncing ? CrossBounce.Clay : null);
            int frames = 0;
            FlightState render = default;
            Action fly = () =>
            {
                driver.Reset(DriverShots.Drive); // the same whole flight every run
                frames = Fly(driver, events, deltas);
                render = driver.RenderState;
            };
            long allocated = Allocation.SteadyStateBytes(fly);
            Assert.That(allocated, Is.EqualTo(0), $"bytes allocated over {frames} frames");
            Assert.That(render.IsFinite, Is.True);
        }

        private static int Fly(FixedStepDriver driver, FlightEvent[] events, double[] deltas)
        {
            int frame = 0;
            while (!driver.IsFinished && frame < 10_000)
            {
                driver.Advance(deltas[frame % deltas.Length], events);
                _ = driver.RenderState;
                frame++;
            }

            return frame;
        }

        [TestCase(double.NaN)]
        [TestCase(-0.001)]
        [TestCase(double.PositiveInfinity)]
        [TestCase(double.NegativeInfinity)]
        public void BadFrameDelta_Throws_AndChangesNothing(double delta)
        {
            FixedStepDriver driver = NewDriver();
            driver.Advance(3.5 * Step);
            FlightState state = driver.State, render = driver.RenderState;
            double accumulator = driver.Accumulator;
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => driver.Advance(delta));
            Assert.That(e!.ParamName, Is.EqualTo("frameDeltaSeconds"));
            Assert.That(e.Message, Does.Contain(">= 0"));
            Assert.That(driver.State.Position, Is.EqualTo(state.Position));
            Assert.That(driver.State.Time, Is.EqualTo(state.Time));
            Assert.That(driver.RenderState.Position, Is.EqualTo(render.Position));
            Assert.That(driver.Accumulator, Is.EqualTo(accumulator));
            Assert.That(driver.TotalSteps, Is.EqualTo(3));
        }

        [Test]
        public void BadConstruction_IsRefused_NamingTheParameter()
        {
            FlightModel model = DriverShots.YUpTennis;
            FlightState good = DriverShots.Drive;
            var bad = new FlightState(new Vector3d(double.NaN, 0, 0), Vector3d.UnitX, Vector3d.Zero);
            Assert.That(Assert.Throws<ArgumentNullException>(() => new FixedStepDriver(null!, RungeKutta4.Instance, Step, good))!.ParamName, Is.EqualTo("model"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => new FixedStepDriver(model, null!, Step, good))!.ParamName, Is.EqualTo("integrator"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new FixedStepDriver(model, RungeKutta4.Instance, 0, good))!.ParamName, Is.EqualTo("fixedStep"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new FixedStepDriver(model, RungeKutta4.Instance, double.NaN, good))!.ParamName, Is.EqualTo("fixedStep"));
            Assert.That(Assert.Throws<ArgumentException>(() => new FixedStepDriver(model, RungeKutta4.Instance, Step, bad))!.ParamName, Is.EqualTo("start"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new FixedStepDriver(model, RungeKutta4.Instance, Step, good, maxFrameDeltaSeconds: 0))!.ParamName, Is.EqualTo("maxFrameDeltaSeconds"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new FixedStepDriver(model, RungeKutta4.Instance, Step, good, maxStepsPerAdvance: -1))!.ParamName, Is.EqualTo("maxStepsPerAdvance"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new FixedStepDriver(model, RungeKutta4.Instance, Step, good, restNormalSpeed: -1))!.ParamName, Is.EqualTo("restNormalSpeed"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new FixedStepDriver(model, RungeKutta4.Instance, Step, good, rollingResistance: double.NaN))!.ParamName, Is.EqualTo("rollingResistance"));
            var noGround = new FlightEventSet(DriverShots.Up);
            Assert.That(Assert.Throws<ArgumentException>(() => new FixedStepDriver(model, RungeKutta4.Instance, Step, good, noGround, CrossBounce.Hard))!.ParamName, Is.EqualTo("bounce"));

            FixedStepDriver driver = NewDriver();
            driver.Advance(0.1);
            FlightState before = driver.State;
            Assert.That(Assert.Throws<ArgumentException>(() => driver.Reset(bad))!.ParamName, Is.EqualTo("start"));
            Assert.That(driver.State.Position, Is.EqualTo(before.Position), "a refused reset changes nothing");
        }

        [Test]
        public void Reset_StartsAgain()
        {
            FixedStepDriver driver = NewDriver();
            while (!driver.IsFinished)
            {
                driver.Advance(0.1);
            }

            driver.Reset(DriverShots.Drive);
            Assert.That(driver.IsFinished, Is.False);
            Assert.That(driver.TotalSteps, Is.EqualTo(0));
            Assert.That(driver.RenderState.Position, Is.EqualTo(DriverShots.Drive.Position));
            Assert.That(driver.Advance(Step).StepsTaken, Is.EqualTo(1));
        }
    }
}
