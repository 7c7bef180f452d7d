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
    /// <summary>Flights through bounces under the driver: the bounce at the exact contact time, determinism, smooth drawing.</summary>
    [TestFixture]
    public class BounceDrivingTests
    {
        private const double Step = 1.0 / 240;

        private static FixedStepDriver NewDriver() =>
            // The driver's ground is where the ball's centre touches (here y = 0), so the court is one radius below.
            new FixedStepDriver(DriverShots.YUpTennis, RungeKutta4.Instance, Step, DriverShots.Drive, bounce: CrossBounce.Hard);

        [Test]
        public void ABufferOfMaximumEventsPerStep_LosesNoEvent_TheRestOfTheFrameIsDeferred()
        {
            // One 20 s frame through a ball bouncing to rest: far more events than any one step makes. With a buffer of
            // MaximumEventsPerStep the driver stops before a step whose events might not fit, keeps that time
            // (StepsDeferred), and the caller's Advance(0, ...) takes it: every event, in the order and with the bits of a
            // driver stepped one fixed step per call. A 16-slot buffer still counts its overflow as lost.
            var reference = new FixedStepDriver(DriverShots.YUpTennis, RungeKutta4.Instance, Step, DriverShots.Drive, bounce: CrossBounce.Hard, maxFrameDeltaSeconds: 30);
            var expected = new List<FlightEvent>();
            var big = new FlightEvent[reference.MaximumEventsPerStep];
            for (int i = 0; i < 100_000 && !reference.IsFinished; i++)
            {
                AdvanceResult r = reference.Advance(Step, big);
                Assert.That(r.EventsNotReported, Is.EqualTo(0));
                for (int k = 0; k < r.EventCount; k++)
                {
                    expected.Add(big[k]);
                }
            }

            var driver = new FixedStepDriver(DriverShots.YUpTennis, RungeKutta4.Instance, Step, DriverShots.Drive, bounce: CrossBounce.Hard, maxFrameDeltaSeconds: 30);
            var seen = new List<FlightEvent>();
            AdvanceResult result = driver.Advance(20, big);
            int deferrals = 0;
            for (int pass = 0; pass < 100_000; pass++)
            {
                Assert.That(result.EventsNotReported, Is.EqualTo(0));
                for (int k = 0; k < result.EventCount; k++)
                {
                    seen.Add(big[k]);
                }

                if (!result.StepsDeferred)
                {
                    break;
                }

                deferrals++;
                result = driver.Advance(0, big);
            }

            Assert.That(driver.IsFinished, Is.True, "the ball came to rest within the frame");
            Assert.That(deferrals, Is.GreaterThan(0), "the frame was deferred");
            Assert.That(expected.Count, Is.GreaterThan(16));
            Assert.That(seen.Count, Is.EqualTo(expected.Count));
            for (int e = 0; e < seen.Count; e++)
            {
                Assert.That((seen[e].Kind, seen[e].Time, seen[e].Position), Is.EqualTo((expected[e].Kind, expected[e].Time, expected[e].Position)), $"event {e}");
            }

            var small = new FixedStepDriver(DriverShots.YUpTennis, RungeKutta4.Instance, Step, DriverShots.Drive, bounce: CrossBounce.Hard, maxFrameDeltaSeconds: 30);
            AdvanceResult once = small.Advance(20, new FlightEvent[16]);
            Assert.That(once.StepsDeferred, Is.False, "a buffer shorter than one step's maximum is never deferred");
            Assert.That(once.EventCount + once.EventsNotReported, Is.EqualTo(expected.Count), "its overflow is counted");
        }

        private static List<FlightEvent> Fly(FixedStepDriver driver, double[] deltas, Action<FixedStepDriver>? perFrame = null)
        {
            var all = new List<FlightEvent>();
            var events = new FlightEvent[16];
            for (int frame = 0; frame < 100_000 && !driver.IsFinished; frame++)
            {
                AdvanceResult result = driver.Advance(deltas[frame % deltas.Length], events);
                Assert.That(result.EventsNotReported, Is.EqualTo(0));
                for (int i = 0; i < result.EventCount; i++)
                {
                    if (events[i].Kind == FlightEventKinds.Bounce || events[i].Kind == FlightEventKinds.Rest)
                    {
                        all.Add(events[i]);
                    }
                }

                perFrame?.Invoke(driver);
            }

            Assert.That(driver.IsFinished, Is.True, "the ball comes to rest");
            Assert.That(driver.Phase, Is.EqualTo(FlightPhase.Stopped));
            return all;
        }

        [Test]
        public void ABounce_IsTheBounceModelAppliedAtTheContactTime()
        {
            List<FlightEvent> touches = Fly(NewDriver(), DriverShots.FixedRate(60, 1));
            TestContext.Out.WriteLine($"{touches.Count - 1} bounces, then stops at {touches[touches.Count - 1].Position} at t = {touches[touches.Count - 1].Time:F2} s");
            Assert.That(touches.Count, Is.GreaterThanOrEqualTo(3), "at least two bounces before it stops");
            Assert.That(touches[0].Kind, Is.EqualTo(FlightEventKinds.Bounce));
            Assert.That(touches[0].StartsRolling, Is.False);
            Assert.That(touches[touches.Count - 2].StartsRolling, Is.True, "the last bounce starts the roll");
            Assert.That(touches[touches.Count - 1].Kind, Is.EqualTo(FlightEventKinds.Rest));

            FlightEvent first = touches[0];
            BounceOutcome expected = CrossBounce.Hard.Bounce(Ball.Tennis, DriverShots.Up, first.State.Velocity, first.State.AngularVelocity);
            Assert.That(first.After.Velocity, Is.EqualTo(expected.Velocity));
            Assert.That(first.After.AngularVelocity, Is.EqualTo(expected.AngularVelocity));
            Assert.That(first.Regime, Is.EqualTo(expected.Regime));
            Assert.That(first.After.Time, Is.EqualTo(first.Time));
            // 1e-12 m: the contact is located to 1e-12 s (queries' HermiteSegment tolerance) at a few m/s down.
            Assert.That(first.Position.Y, Is.EqualTo(0).Within(1e-10));
            Assert.That(first.After.Velocity.Y, Is.GreaterThan(GroundContact.DefaultRestNormalSpeed));

            // The bounces, and then the stop, move on down the court.
            for (int i = 1; i < touches.Count; i++)
            {
                Assert.That(touches[i].Time, Is.GreaterThan(touches[i - 1].Time));
                Assert.That(touches[i].Position.X, Is.GreaterThan(touches[i - 1].Position.X));
            }
        }

        [Test]
        public void MultiBounceFlights_AreTheSameBits_AtEveryFrameRate()
        {
            List<FlightEvent> reference = Fly(NewDriver(), DriverShots.FixedRate(60, 1));
            foreach (double[] deltas in new[]
            {
                DriverShots.FixedRate(30, 1), DriverShots.FixedRate(144, 1), DriverShots.Jittery(99, 300), DriverShots.WithHitch(30, 300),
            })
            {
                List<FlightEvent> touches = Fly(NewDriver(), deltas);
                Assert.That(touches.Count, Is.EqualTo(reference.Count));
                for (int i = 0; i < touches.Count; i++)
                {
                    Assert.That(touches[i].Position, Is.EqualTo(reference[i].Position), $"touch {i}");
                    Assert.That(touches[i].Time, Is.EqualTo(reference[i].Time), $"touch {i}");
                    Assert.That(touches[i].After.Velocity, Is.EqualTo(reference[i].After.Velocity), $"touch {i}");
                    Assert.That(touches[i].Kind, Is.EqualTo(reference[i].Kind), $"touch {i}");
                }
            }
        }

        [Test]
        public void TheDrawnBall_MovesSmoothlyThroughTheBounce()
        {
            // At 144 FPS the drawn ball never moves more than the fastest speed times a frame, and never goes
            // below the ground, also in the frames around each bounce and while it rolls.
            double frame = 1.0 / 144;
            Vector3d last = DriverShots.Drive.Position;
            double maxSpeed = DriverShots.Drive.Velocity.Length;
            int frames = 0;
            Fly(NewDriver(), new[] { frame }, driver =>
            {
                Vector3d now = driver.RenderState.Position;
                // 1e-9: round-off on metre-sized numbers.
                Assert.That(Vector3d.Distance(now, last), Is.LessThanOrEqualTo(maxSpeed * frame + 1e-9), $"frame {frames}");
                // 1e-9 m: the Hermite of the step cut at the contact ends on the ground to the contact tolerance.
                Assert.That(now.Y, Is.GreaterThanOrEqualTo(-1e-9), $"frame {frames}");
                last = now;
                frames++;
            });
        }
    }
}
