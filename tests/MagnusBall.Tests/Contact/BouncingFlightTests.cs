using System;
using MagnusBall.Flight;
using MagnusBall.Aerodynamics;
using MagnusBall.Contact;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>A bouncing flight is the flight core with a contact surface; these two calls keep the tests short.</summary>
    internal static class Bouncing
    {
        public static FlightStepper Start(
            FlightModel model, IIntegrator integrator, IBounceModel bounce, Plane plane, in FlightState start,
            double restNormalSpeed = GroundContact.DefaultRestNormalSpeed, double rollingResistance = GroundContact.DefaultRollingResistance)
        {
            var stepper = new FlightStepper(model, integrator, null, new GroundContact(bounce, plane, restNormalSpeed, rollingResistance));
            stepper.Reset(start);
            return stepper;
        }

        /// <summary>One step; writes the step's bounces to <paramref name="bounces"/> and returns how many there were.</summary>
        public static int Step(FlightStepper flight, double step, Span<FlightEvent> bounces)
        {
            if (flight.TryStep(step) == StepOutcome.Diverged)
            {
                Assert.Fail($"the step diverged at {flight.State}");
            }

            int n = 0;
            foreach (FlightEvent e in flight.Events)
            {
                if (e.Kind == FlightEventKinds.Bounce)
                {
                    if (n < bounces.Length)
                    {
                        bounces[n] = e;
                    }

                    n++;
                }
            }

            return n;
        }

        /// <summary>Where the ball touches the surface: its centre one radius down the surface normal.</summary>
        public static Vector3d ContactPoint(this in FlightEvent bounce, FlightStepper flight) =>
            bounce.Position - flight.Contact!.Plane.Normal * flight.Model.Ball.Radius;
    }

    /// <summary>A flight through bounces: event location, the bounce at the contact time, rest, frames, allocation.</summary>
    [TestFixture]
    public class BouncingFlightTests
    {
        private static readonly Surface Bouncy = new Surface("test 0.8", 0.8, 0, 0.5, 0.1, 0, 0);

        private static FlightModel Tennis(Vector3d gravity) =>
            new FlightModel(Ball.Tennis, new Air(1.21), gravity, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));

        private static FlightStepper Run(FlightStepper flight, double step, int maxSteps, FlightEvent[] log, ref int logged)
        {
            Span<FlightEvent> buffer = stackalloc FlightEvent[4];
            for (int i = 0; i < maxSteps && flight.Phase != FlightPhase.Stopped; i++)
            {
                int n = Bouncing.Step(flight, step, buffer);
                for (int k = 0; k < Math.Min(n, buffer.Length); k++)
                {
                    if (logged < log.Length)
                    {
                        log[logged++] = buffer[k];
                    }
                }
            }

            return flight;
        }

        [Test]
        public void VerticalDropInVacuum_BouncesAtTheExactTimes()
        {
            // Centre 1 m above the contact height; each bounce keeps e = 0.8 of the normal speed.
            const double g = Gravity.Standard, e = 0.8, drop = 1.0;
            var model = FlightModel.Vacuum(Ball.Tennis, Gravity.ZUp);
            var ground = new Plane(Vector3d.Zero, Vector3d.UnitZ);
            var start = new FlightState(new Vector3d(0, 0, drop + Ball.Tennis.Radius), Vector3d.Zero, Vector3d.Zero);
            var flight = Bouncing.Start(model, RungeKutta4.Instance, new CrossBounce(Bouncy), ground, start);
            var log = new FlightEvent[64];
            int logged = 0;
            Run(flight, 1.0 / 60, 10_000, log, ref logged);

            double v = Math.Sqrt(2 * g * drop), t = Math.Sqrt(2 * drop / g);
            for (int i = 0; i < 5; i++)
            {
                TestContext.Out.WriteLine($"bounce {(i + 1)}: t {log[i].Time:F12} s (exact {t:F12}), v_in {-log[i].State.Velocity.Z:F12} m/s (exact {v:F12})");
                // RK4 is exact for this quadratic motion and the Hermite cubic reproduces it: event tolerance 1e-12 s, plus rounding.
                Assert.That(log[i].Time, Is.EqualTo(t).Within(1e-10), $"bounce {i + 1}");
                Assert.That(-log[i].State.Velocity.Z, Is.EqualTo(v).Within(1e-9), $"bounce {i + 1}");
                Assert.That(log[i].ContactPoint(flight).Z, Is.EqualTo(0).Within(1e-15));
                Assert.That(log[i].Position.Z, Is.EqualTo(Ball.Tennis.Radius).Within(1e-15));
                v *= e;
                t += 2 * v / g;
            }

            // It settles: the rest condition ends the bouncing after finitely many bounces (v e^k < 0.1 m/s).
            Assert.That(flight.Phase, Is.EqualTo(FlightPhase.Stopped));
            int expected = (int)Math.Ceiling(Math.Log(GroundContact.DefaultRestNormalSpeed / Math.Sqrt(2 * g * drop)) / Math.Log(e));
            Assert.That(flight.BounceCount, Is.EqualTo(expected));
            Assert.That(flight.State.Position.Z, Is.EqualTo(Ball.Tennis.Radius).Within(1e-15));
        }

        [Test]
        public void StepsKeepTheFixedTimeGrid_ThroughBounces()
        {
            var model = Tennis(Gravity.ZUp);
            var start = Shots.ZUpDrive(new Vector3d(0, 200, 0), 25, 5);
            var flight = Bouncing.Start(model, RungeKutta4.Instance, CrossBounce.Hard, Plane.Ground(model), start);
            const double h = 1.0 / 120;
            double expected = 0;
            for (int i = 0; i < 1200; i++)
            {
                Bouncing.Step(flight, h, Span<FlightEvent>.Empty);
                expected += h;
                Assert.That(flight.State.Time, Is.EqualTo(expected), $"step {i}");
            }

            Assert.That(flight.BounceCount, Is.GreaterThanOrEqualTo(2));
        }

        [Test]
        public void BouncePoints_ConvergeWithTheStep_NotLimitedToAStep()
        {
            // The second bounce depends on the first being applied at the exact contact time.
            var model = Tennis(Gravity.ZUp);
            var start = Shots.ZUpDrive(Spin.Topspin(new Vector3d(1, 0, 0), Vector3d.UnitZ, Spin.FromRpm(2500)), 28, 6);
            Vector3d[] Points(double step)
            {
                var flight = Bouncing.Start(model, RungeKutta4.Instance, CrossBounce.Hard, Plane.Ground(model), start);
                var log = new FlightEvent[8];
                int logged = 0;
                Run(flight, step, (int)(6 / step), log, ref logged);
                Assert.That(logged, Is.GreaterThanOrEqualTo(2));
                return new[] { log[0].ContactPoint(flight), log[1].ContactPoint(flight) };
            }

            Vector3d[] coarse = Points(1.0 / 60), fine = Points(1.0 / 960);
            double first = Vector3d.Distance(coarse[0], fine[0]), second = Vector3d.Distance(coarse[1], fine[1]);
            TestContext.Out.WriteLine($"first bounce {fine[0]}, second {fine[1]}; 1/60 s vs 1/960 s: {first:E2} m, {second:E2} m");
            // A step at 1/60 s moves the ball ~0.4 m; RK4 with Hermite event location is within micrometres.
            Assert.That(first, Is.LessThan(1e-5));
            Assert.That(second, Is.LessThan(1e-5));
        }

        [Test]
        public void AShot_BouncesRollsAndStops()
        {
            var model = Tennis(Gravity.ZUp);
            var start = Shots.ZUpDrive(Spin.Topspin(new Vector3d(1, 0, 0), Vector3d.UnitZ, Spin.FromRpm(2000)), 30, 6);
            foreach (Surface surface in Surface.Courts)
            {
                var flight = Bouncing.Start(model, RungeKutta4.Instance, new CrossBounce(surface), Plane.Ground(model), start);
                var log = new FlightEvent[64];
                int logged = 0;
                Run(flight, 1.0 / 240, 240 * 120, log, ref logged);
                FlightEvent first = log[0], second = log[1];
                TestContext.Out.WriteLine(
                    $"{surface.Name}: first bounce at x {first.ContactPoint(flight).X:F3} m, out {first.After.Velocity.Length:F2} m/s " +
                    $"{Math.Atan2(first.After.Velocity.Z, first.After.Velocity.X) * 180 / Math.PI:F1} deg " +
                    $"{Spin.ToRpm(first.After.AngularVelocity.Y):F0} rpm ({first.Regime}); second at x {second.ContactPoint(flight).X:F3} m; " +
                    $"{flight.BounceCount} bounces, stopped at x {flight.State.Position.X:F2} m, t {flight.State.Time:F2} s");
                Assert.That(flight.Phase, Is.EqualTo(FlightPhase.Stopped), surface.Name);
                Assert.That(second.ContactPoint(flight).X, Is.GreaterThan(first.ContactPoint(flight).X));
                Assert.That(flight.State.Velocity, Is.EqualTo(Vector3d.Zero));
                Assert.That(flight.State.Position.Z, Is.EqualTo(Ball.Tennis.Radius).Within(1e-12));
                Assert.That(flight.State.Position.X, Is.GreaterThan(second.ContactPoint(flight).X));
            }
        }

        [Test]
        public void Rolling_OnLevelGround_StopsAfterVSquaredOverTwoDecelerations()
        {
            // A grazing ball: outgoing normal speed below the rest threshold, so the first contact starts rolling.
            var model = FlightModel.Vacuum(Ball.Tennis, Gravity.ZUp);
            var start = new FlightState(new Vector3d(0, 0, Ball.Tennis.Radius + 1e-4), new Vector3d(3, 0, -0.05), Vector3d.Zero);
            const double crr = 0.05;
            var flight = Bouncing.Start(model, RungeKutta4.Instance, CrossBounce.Hard, Plane.Ground(model), start, 0.1, crr);
            var log = new FlightEvent[4];
            int logged = 0;
            Run(flight, 1.0 / 60, 60 * 60, log, ref logged);
            Assert.That(logged, Is.EqualTo(1));
            Assert.That(log[0].StartsRolling, Is.True);
            // Rolling speed keeps the angular momentum about the contact point: Lam / (1 + alpha).
            double vx = log[0].After.Velocity.X, rw = Ball.Tennis.Radius * log[0].After.AngularVelocity.Y;
            double rolling = (vx + Ball.Tennis.InertiaFactor * rw) / (1 + Ball.Tennis.InertiaFactor);
            double distance = rolling * rolling / (2 * crr * Gravity.Standard);
            Assert.That(flight.Phase, Is.EqualTo(FlightPhase.Stopped));
            // Closed form on level ground: rounding only.
            Assert.That(flight.State.Position.X - log[0].Position.X, Is.EqualTo(distance).Within(1e-12));
        }

        [Test]
        public void TheSameFlight_BouncesAtTheSamePoints_InZUpAndUnityFrames()
        {
            var zUp = Court.ZUp.Frame;
            var unity = Court.Unity.Frame;
            Vector3d[] Points(Behavior.SpinSignTests.Frame frame)
            {
                var model = Tennis(frame.Up * -Gravity.Standard);
                Vector3d v = frame.Map(26, 2, 5);
                Vector3d w = Spin.Topspin(v, frame.Up, Spin.FromRpm(2200)) + Spin.Toward(v, frame.Left, Spin.FromRpm(800));
                var flight = Bouncing.Start(model, RungeKutta4.Instance, CrossBounce.Clay, Plane.Ground(model), new FlightState(frame.Map(0, 0, 1), v, w));
                var log = new FlightEvent[8];
                int logged = 0;
                Run(flight, 1.0 / 240, 240 * 4, log, ref logged);
                Assert.That(logged, Is.GreaterThanOrEqualTo(3));
                var result = new Vector3d[3];
                for (int i = 0; i < 3; i++)
                {
                    Vector3d p = log[i].ContactPoint(flight);
                    result[i] = new Vector3d(Vector3d.Dot(p, frame.Forward), Vector3d.Dot(p, frame.Left), Vector3d.Dot(p, frame.Up));
                }

                return result;
            }

            Vector3d[] a = Points(zUp), b = Points(unity);
            for (int i = 0; i < 3; i++)
            {
                TestContext.Out.WriteLine($"bounce {i + 1}: z-up {a[i]}, Unity {b[i]} (forward, left, up)");
                // Same arithmetic on permuted, sign-flipped components: rounding over a few hundred steps.
                Assert.That(Vector3d.Distance(a[i], b[i]), Is.LessThan(1e-9), $"bounce {i + 1}");
            }

            Assert.That(Math.Abs(a[0].Y), Is.GreaterThan(0.1), "the side spin should move the ball sideways");
        }

        [Test]
        public void MultiBounceFlight_IsBitwiseTheSame_WhateverTheFrameRate()
        {
            // Frame time turned into fixed steps with an accumulator and the 0.25 s clamp (Fiedler), as the
            // fixed-step driver does; the bounce points must not depend on how frame time was sliced.
            const double step = 1.0 / 240;
            FlightEvent[] Bounces(double[] deltas)
            {
                var model = Stepping.DriverShots.YUpTennis;
                var flight = Bouncing.Start(model, RungeKutta4.Instance, CrossBounce.Hard, Plane.Ground(model), Stepping.DriverShots.Drive);
                var log = new FlightEvent[4];
                int logged = 0;
                Span<FlightEvent> buffer = stackalloc FlightEvent[4];
                double accumulator = 0;
                for (int frame = 0; logged < log.Length && frame < 100_000; frame++)
                {
                    accumulator += Math.Min(deltas[frame % deltas.Length], 0.25);
                    while (accumulator >= step && logged < log.Length)
                    {
                        accumulator -= step;
                        int n = Bouncing.Step(flight, step, buffer);
                        for (int k = 0; k < n && logged < log.Length; k++)
                        {
                            log[logged++] = buffer[k];
                        }
                    }
                }

                Assert.That(logged, Is.EqualTo(log.Length));
                return log;
            }

            FlightEvent[] reference = Bounces(Stepping.DriverShots.FixedRate(60, 1));
            foreach ((string name, double[] deltas) in new[]
            {
                ("30 FPS", Stepping.DriverShots.FixedRate(30, 60)),
                ("144 FPS", Stepping.DriverShots.FixedRate(144, 288)),
                ("jittery 5-50 ms", Stepping.DriverShots.Jittery(20261124, 400)),
                ("60 FPS, 0.5 s hitch", Stepping.DriverShots.WithHitch(20, 400)),
            })
            {
                FlightEvent[] bounces = Bounces(deltas);
                for (int i = 0; i < reference.Length; i++)
                {
                    // Bitwise: exact equality, no tolerance.
                    Assert.That(bounces[i].Position, Is.EqualTo(reference[i].Position), $"{name}, bounce {i + 1}");
                    Assert.That(bounces[i].Time, Is.EqualTo(reference[i].Time), $"{name}, bounce {i + 1}");
                    Assert.That(bounces[i].After.Velocity, Is.EqualTo(reference[i].After.Velocity), $"{name}, bounce {i + 1}");
                    Assert.That(bounces[i].After.AngularVelocity, Is.EqualTo(reference[i].After.AngularVelocity), $"{name}, bounce {i + 1}");
                }
            }

            TestContext.Out.WriteLine($"bounces (centre) at {reference[0].Position}, {reference[1].Position}, {reference[2].Position}");
        }

        [TestCase(10.0)]
        [TestCase(0.05)]
        public void AWall_BouncesTheBallBack_AndNeverHoldsIt(double speed)
        {
            // A vertical wall (normal -x) in a z-up world: gravity does not press the ball into it, so even a
            // bounce slower than the rest threshold flies on instead of rolling.
            var model = FlightModel.Vacuum(Ball.Tennis, Gravity.ZUp);
            var wall = new Plane(new Vector3d(1, 0, 0), -Vector3d.UnitX);
            var start = new FlightState(new Vector3d(1 - Ball.Tennis.Radius - 0.005, 0, 2), new Vector3d(speed, 0, 0), new Vector3d(0, 100, 0));
            var flight = Bouncing.Start(model, RungeKutta4.Instance, CrossBounce.Hard, wall, start);
            var log = new FlightEvent[4];
            int logged = 0;
            Run(flight, 1.0 / 120, 240, log, ref logged);
            Assert.That(logged, Is.EqualTo(1));
            Assert.That(log[0].StartsRolling, Is.False);
            Assert.That(flight.Phase, Is.EqualTo(FlightPhase.Flying));
            Assert.That(log[0].Position.X, Is.EqualTo(1 - Ball.Tennis.Radius).Within(1e-15));
            // Back off the wall at e_y of the incoming normal speed (the normal is -x).
            BounceOutcome law = CrossBounce.Hard.Bounce(model.Ball, wall.Normal, log[0].State.Velocity, log[0].State.AngularVelocity);
            Assert.That(log[0].After.Velocity, Is.EqualTo(law.Velocity), "the bounce is the law applied at the contact");
            Assert.That(-log[0].After.Velocity.X, Is.EqualTo(law.NormalRestitution * log[0].State.Velocity.X).Within(1e-12));
            Assert.That(flight.State.Velocity.X, Is.LessThan(0));
            Assert.That(flight.State.Position.X, Is.LessThan(1 - Ball.Tennis.Radius));
        }

        [Test]
        public void RandomShots_StayFiniteAndAboveTheCourt_AndComeToRest()
        {
            var random = new Random(42);
            Surface[] courts = Surface.Courts;
            for (int shot = 0; shot < 60; shot++)
            {
                Court court = Court.All[shot % 3];
                var model = Tennis(court.Frame.Up * -Gravity.Standard);
                Vector3d v = court.Frame.Map(5 + 45 * random.NextDouble(), 10 * random.NextDouble() - 5, 20 * random.NextDouble() - 8);
                Vector3d w = CrossBounceTests.RandomUnit(random) * (600 * random.NextDouble());
                var start = new FlightState(court.Frame.Map(0, 0, 0.3 + 2.7 * random.NextDouble()), v, w);
                var flight = Bouncing.Start(model, RungeKutta4.Instance, new CrossBounce(courts[shot % 3]), Plane.Ground(model), start);
                int steps = 0;
                while (flight.Phase != FlightPhase.Stopped && steps < 120 * 120)
                {
                    Bouncing.Step(flight, 1.0 / 120, Span<FlightEvent>.Empty);
                    steps++;
                    Assert.That(flight.State.IsFinite, Is.True, $"shot {shot}, step {steps}");
                    // The centre never ends a step below the contact height (one radius), beyond rounding.
                    Assert.That(court.Up(flight.State.Position), Is.GreaterThan(Ball.Tennis.Radius - 1e-9), $"shot {shot}, step {steps}");
                }

                Assert.That(flight.Phase, Is.EqualTo(FlightPhase.Stopped), $"shot {shot}: {flight.BounceCount} bounces");
            }
        }

        [Test]
        public void ABallPlacedOnTheCourt_RestsThere_OrRollsToAStop()
        {
            var model = Tennis(Gravity.YUp);
            double r = Ball.Tennis.Radius;
            var resting = Bouncing.Start(model, RungeKutta4.Instance, CrossBounce.Hard, Plane.Ground(model),
                new FlightState(new Vector3d(1, r, 2), Vector3d.Zero, Vector3d.Zero));
            Assert.That(resting.Phase, Is.EqualTo(FlightPhase.Rolling));
            Bouncing.Step(resting, 1.0 / 60, Span<FlightEvent>.Empty);
            Assert.That(resting.Phase, Is.EqualTo(FlightPhase.Stopped));
            Assert.That(resting.State.Position, Is.EqualTo(new Vector3d(1, r, 2)));

            // Pushed along the court at 2 m/s without spin: it rolls at 2/(1 + alpha) and stops (no drag in vacuum).
            var vacuum = FlightModel.Vacuum(Ball.Tennis, Gravity.YUp);
            var pushed = Bouncing.Start(vacuum, RungeKutta4.Instance, CrossBounce.Hard, Plane.Ground(vacuum),
                new FlightState(new Vector3d(0, r, 0), new Vector3d(0, 0, 2), Vector3d.Zero));
            Assert.That(pushed.State.Velocity.Z, Is.EqualTo(2 / (1 + Ball.Tennis.InertiaFactor)).Within(1e-15));
            for (int i = 0; i < 60 * 30 && pushed.Phase != FlightPhase.Stopped; i++)
            {
                Bouncing.Step(pushed, 1.0 / 60, Span<FlightEvent>.Empty);
            }

            double v = 2 / (1 + Ball.Tennis.InertiaFactor);
            Assert.That(pushed.Phase, Is.EqualTo(FlightPhase.Stopped));
            // Closed form on level ground: rounding only.
            Assert.That(pushed.State.Position.Z, Is.EqualTo(v * v / (2 * GroundContact.DefaultRollingResistance * Gravity.Standard)).Within(1e-12));
            Assert.That(pushed.State.Position.Y, Is.EqualTo(r).Within(1e-15));
        }

        [Test]
        public void StateAt_FollowsTheBounce_InsideTheStep()
        {
            var model = FlightModel.Vacuum(Ball.Tennis, Gravity.ZUp);
            var start = new FlightState(new Vector3d(0, 0, 0.5 + Ball.Tennis.Radius), new Vector3d(2, 0, 0), Vector3d.Zero);
            var flight = Bouncing.Start(model, RungeKutta4.Instance, new CrossBounce(Bouncy), Plane.Ground(model), start);
            Span<FlightEvent> one = stackalloc FlightEvent[1];
            while (Bouncing.Step(flight, 0.05, one) == 0)
            {
            }

            double tc = one[0].Time;
            Assert.That(flight.StateAt(tc).Position.Z, Is.EqualTo(Ball.Tennis.Radius).Within(1e-12));
            Assert.That(flight.StateAt(tc - 1e-3).Velocity.Z, Is.LessThan(0));
            Assert.That(flight.StateAt(tc + 1e-3).Velocity.Z, Is.GreaterThan(0));
            Assert.That(flight.StateAt(tc + 1e-3).Position.Z, Is.GreaterThan(Ball.Tennis.Radius));
            Assert.That(flight.StateAt(flight.State.Time).Position, Is.EqualTo(flight.State.Position));
        }

        [Test]
        public void AWholeMultiBounceFlight_AllocatesNothing()
        {
            var model = Tennis(Gravity.ZUp);
            var start = Shots.ZUpDrive(new Vector3d(0, 150, 30), 25, 8);
            var flight = Bouncing.Start(model, RungeKutta4.Instance, CrossBounce.Grass, Plane.Ground(model), start);
            var buffer = new FlightEvent[4];
            int bounces = 0;
            Action fly = () =>
            {
                flight.Reset(start); // the same whole flight every run
                bounces = Fly(flight, buffer);
            };

            long allocated = Allocation.SteadyStateBytes(fly);
            Assert.That(allocated, Is.EqualTo(0));
            Assert.That(bounces, Is.GreaterThan(3));
            Assert.That(flight.Phase, Is.EqualTo(FlightPhase.Stopped));
        }

        private static int Fly(FlightStepper flight, FlightEvent[] buffer)
        {
            int bounces = 0;
            for (int i = 0; i < 240 * 60 && flight.Phase != FlightPhase.Stopped; i++)
            {
                bounces += Bouncing.Step(flight, 1.0 / 240, buffer);
                _ = flight.StateAt(flight.State.Time - 1.0 / 480);
            }

            return bounces;
        }

        [Test]
        public void BadArguments_AreRefused()
        {
            var model = Tennis(Gravity.ZUp);
            var start = Shots.ZUpDrive(Vector3d.Zero);
            var ground = Plane.Ground(model);
            Assert.That(() => Bouncing.Start(null!, RungeKutta4.Instance, CrossBounce.Hard, ground, start),
                Throws.InstanceOf<ArgumentNullException>().With.Property("ParamName").EqualTo("model"));
            Assert.That(() => Bouncing.Start(model, RungeKutta4.Instance, null!, ground, start),
                Throws.InstanceOf<ArgumentNullException>().With.Property("ParamName").EqualTo("bounce"));
            Assert.That(() => Bouncing.Start(model, RungeKutta4.Instance, CrossBounce.Hard, default, start),
                Throws.ArgumentException.With.Property("ParamName").EqualTo("plane"));
            Assert.That(() => Bouncing.Start(model, RungeKutta4.Instance, CrossBounce.Hard, ground, start, double.NaN),
                Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("restNormalSpeed"));
            Assert.That(() => Bouncing.Start(model, RungeKutta4.Instance, CrossBounce.Hard, ground, start, 0.1, -1),
                Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("rollingResistance"));
            Assert.That(() => Bouncing.Start(model, RungeKutta4.Instance, CrossBounce.Hard, ground, new FlightState(new Vector3d(double.NaN, 0, 1), default, default)),
                Throws.ArgumentException.With.Property("ParamName").EqualTo("state"));
            var flight = Bouncing.Start(model, RungeKutta4.Instance, CrossBounce.Hard, ground, start);
            Assert.That(() => Bouncing.Step(flight, 0, Span<FlightEvent>.Empty), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("step"));
            Assert.That(() => Bouncing.Step(flight, double.NaN, Span<FlightEvent>.Empty), Throws.InstanceOf<ArgumentOutOfRangeException>());
            Assert.That(flight.State.Time, Is.EqualTo(0));
        }
    }
}
