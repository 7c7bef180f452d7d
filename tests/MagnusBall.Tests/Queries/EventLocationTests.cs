using System;
using MagnusBall.Flight;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Queries
{
    /// <summary>Dense output and event location on the cubic Hermite of each step.</summary>
    [TestFixture]
    public class EventLocationTests
    {
        /// <summary>A tennis drive that lands about 24 m away: 30 m/s at 12 deg from 1 m with 20 rev/s topspin (Stepanek model).</summary>
        internal static FlightState TennisDrive(Vector3d up)
        {
            var model = Shots.StepanekTennis(Gravity.Along(up));
            double e = 12 * Math.PI / 180;
            Vector3d forward = Math.Abs(up.X) < 0.9 ? Vector3d.UnitX : Vector3d.UnitY;
            Vector3d velocity = 30 * (Math.Cos(e) * forward + Math.Sin(e) * up);
            return new FlightState(up * 1.0, velocity, Spin.Topspin(velocity, up, Spin.FromRevolutionsPerSecond(20)));
        }

        private static FlightEvent FlyToLanding(FlightModel model, IIntegrator integrator, FlightState start, double step)
        {
            var stepper = new FlightStepper(model, integrator, FlightEventSet.ForModel(model));
            stepper.Reset(start);
            while (stepper.State.Time < 10)
            {
                stepper.TryStep(step);
                if (stepper.TryGetEvent(FlightEventKinds.Landing, out FlightEvent landing))
                {
                    return landing;
                }
            }

            throw new AssertionException("no landing within 10 s");
        }

        [Test]
        public void Segment_IsExactAtBothEnds()
        {
            var model = Shots.StepanekTennis(Gravity.ZUp);
            FlightState s0 = TennisDrive(Vector3d.UnitZ);
            StateDerivative d0 = model.Derivative(s0);
            FlightState s1 = ((IIntegrator)RungeKutta4.Instance).Step(model, s0, d0, 1.0 / 60);
            var segment = new HermiteSegment(s0, d0, s1, model.Derivative(s1));

            Assert.That(segment.PositionAt(s0.Time), Is.EqualTo(s0.Position));
            Assert.That((segment.PositionAt(s1.Time) - s1.Position).Length, Is.LessThan(1e-14));
            Assert.That((segment.VelocityAt(s1.Time) - s1.Velocity).Length, Is.LessThan(1e-13));
            Assert.That((segment.AngularVelocityAt(s1.Time) - s1.AngularVelocity).Length, Is.LessThan(1e-13));
            Assert.That(segment.Duration, Is.EqualTo(1.0 / 60).Within(1e-15));
        }

        [Test]
        public void VacuumParabola_LandingAndApex_AreExact()
        {
            // RK4 and the cubic Hermite both reproduce a parabola exactly, so the events are exact
            // up to the 1e-12 s root tolerance and rounding.
            var g = 9.81;
            var model = FlightModel.Vacuum(Ball.Tennis, new Vector3d(0, 0, -g));
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(20, 0, 5), default);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model));
            stepper.Reset(start);
            FlightEvent apex = default, landing = default;
            bool sawApex = false, sawLanding = false;
            while (!sawLanding)
            {
                stepper.TryStep(1.0 / 30);
                sawApex |= stepper.TryGetEvent(FlightEventKinds.Apex, out FlightEvent a) && (apex = a).Time > 0;
                sawLanding = stepper.TryGetEvent(FlightEventKinds.Landing, out landing);
            }

            double landingTime = (5 + Math.Sqrt(25 + 2 * g * 1)) / g;
            Assert.That(sawApex, Is.True);
            Assert.That(apex.Time, Is.EqualTo(5 / g).Within(1e-11));
            Assert.That(apex.Position.Z, Is.EqualTo(1 + 25 / (2 * g)).Within(1e-11));
            Assert.That(landing.Time, Is.EqualTo(landingTime).Within(1e-11));
            Assert.That(landing.Position.X, Is.EqualTo(20 * landingTime).Within(1e-10));
            Assert.That(landing.Position.Z, Is.EqualTo(0).Within(1e-10));
            Assert.That(landing.Velocity.Z, Is.EqualTo(5 - g * landingTime).Within(1e-10));
        }

        // RK4 at 1/60 s and 1/240 s against RK4 at 1/15360 s (64x and 256x smaller steps: its own error is
        // below 1e-12 m, far under the bounds the issue sets, 1e-5 m and 1e-6 m).
        [TestCase(60, 1e-5)]
        [TestCase(240, 1e-6)]
        public void TennisDriveLanding_KeepsRk4Order(int stepsPerSecond, double bound)
        {
            var model = Shots.StepanekTennis(Gravity.ZUp);
            FlightState start = TennisDrive(Vector3d.UnitZ);
            FlightEvent reference = FlyToLanding(model, RungeKutta4.Instance, start, 1.0 / 15360);
            FlightEvent landing = FlyToLanding(model, RungeKutta4.Instance, start, 1.0 / stepsPerSecond);

            double error = Vector3d.Distance(landing.Position, reference.Position);
            TestContext.Out.WriteLine(
                $"landing x = {reference.Position.X:F6} m; RK4 1/{stepsPerSecond} s: error {error:E2} m, time error {Math.Abs(landing.Time - reference.Time):E2} s");
            Assert.That(reference.Position.X, Is.InRange(23, 25), "the case is a ~24 m drive");
            Assert.That(error, Is.LessThan(bound));
        }

        [Test]
        public void TennisDriveApexAndNetCrossing_KeepRk4Order()
        {
            var model = Shots.StepanekTennis(Gravity.ZUp);
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            FlightState start = TennisDrive(Vector3d.UnitZ);
            var events = new FlightEvent[4];

            FlightEvent Find(double step, FlightEventKinds kind)
            {
                var predictor = new TrajectoryPredictor(model, RungeKutta4.Instance, step, FlightEventSet.ForModel(model, net));
                Prediction p = predictor.Predict(start, 10, Span<FlightState>.Empty, events, kind);
                return p.StopEvent;
            }

            foreach (FlightEventKinds kind in new[] { FlightEventKinds.Apex, FlightEventKinds.PlaneCrossing })
            {
                FlightEvent reference = Find(1.0 / 15360, kind);
                FlightEvent coarse = Find(1.0 / 60, kind);
                double error = Vector3d.Distance(coarse.Position, reference.Position);
                TestContext.Out.WriteLine($"{kind} at t {reference.Time:F6} s; RK4 1/60 s: position error {error:E2} m");
                Assert.That(coarse.Kind, Is.EqualTo(kind));

                // The same bound as the landing at 1/60 s (1e-5 m): the apex uses the velocity interpolant,
                // the net crossing the position interpolant, both O(h^4).
                Assert.That(error, Is.LessThan(1e-5), kind.ToString());
            }
        }

        [Test]
        public void FirstStepBelowGround_MissesByFarMore()
        {
            var model = Shots.StepanekTennis(Gravity.ZUp);
            FlightState start = TennisDrive(Vector3d.UnitZ);
            FlightEvent reference = FlyToLanding(model, RungeKutta4.Instance, start, 1.0 / 15360);

            // The naive way: the first step end below the ground is "the landing".
            var stepper = new FlightStepper(model, RungeKutta4.Instance);
            stepper.Reset(start);
            while (stepper.State.Position.Z > 0)
            {
                stepper.TryStep(1.0 / 60);
            }

            double naive = Vector3d.Distance(stepper.State.Position, reference.Position);
            TestContext.Out.WriteLine($"first step below ground at 1/60 s: off by {naive:F3} m");

            // At 1/60 s the ball moves ~0.4 m per step; the step end falls anywhere in it, so it is off by
            // a sizeable fraction of that, orders of magnitude above the Hermite event's 1e-5 m.
            Assert.That(naive, Is.GreaterThan(1e-3));
        }

        [Test]
        public void CrossingDirection_IsRespected()
        {
            var model = FlightModel.Vacuum(Ball.Tennis, Gravity.ZUp);
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(10, 0, 0), default);
            StateDerivative d0 = model.Derivative(start);
            FlightState end = ((IIntegrator)RungeKutta4.Instance).Step(model, start, d0, 0.1);
            var segment = new HermiteSegment(start, d0, end, model.Derivative(end));

            var net = new Plane(new Vector3d(0.5, 0, 0), Vector3d.UnitX);
            Assert.That(segment.TryFindCrossing(net, CrossingDirection.AlongNormal, out double t), Is.True);
            Assert.That(t, Is.EqualTo(0.05).Within(1e-12));
            Assert.That(segment.TryFindCrossing(net, CrossingDirection.AgainstNormal, out _), Is.False);
            Assert.That(segment.TryFindCrossing(net.Flipped(), CrossingDirection.AgainstNormal, out double t2), Is.True);
            Assert.That(t2, Is.EqualTo(0.05).Within(1e-12));

            // A plane the ball does not reach inside the step.
            Assert.That(segment.TryFindCrossing(new Plane(new Vector3d(2, 0, 0), Vector3d.UnitX), CrossingDirection.AlongNormal, out _), Is.False);
        }

        [Test]
        public void CrossingInsideStep_IsFoundWhenBothEndsAreOnTheSameSide()
        {
            // Straight up and back down within one long step: the ball passes a plane at 1 m above its
            // start going up, and both step ends are below it.
            var model = FlightModel.Vacuum(Ball.Tennis, new Vector3d(0, 0, -10));
            var start = new FlightState(default, new Vector3d(1, 0, 10), default);
            StateDerivative d0 = model.Derivative(start);
            FlightState end = ((IIntegrator)RungeKutta4.Instance).Step(model, start, d0, 2.0);
            var segment = new HermiteSegment(start, d0, end, model.Derivative(end));

            var ceiling = new Plane(new Vector3d(0, 0, 1), Vector3d.UnitZ);
            Assert.That(segment.TryFindCrossing(ceiling, CrossingDirection.AlongNormal, out double up), Is.True);
            Assert.That(segment.TryFindCrossing(ceiling, CrossingDirection.AgainstNormal, out double down), Is.True);
            Assert.That(up, Is.EqualTo((10 - Math.Sqrt(80)) / 10).Within(1e-12));
            Assert.That(down, Is.EqualTo((10 + Math.Sqrt(80)) / 10).Within(1e-12));
        }

        [Test]
        public void BallStartingOnTheGround_HasNotLanded()
        {
            var model = FlightModel.Vacuum(Ball.Tennis, Gravity.ZUp);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model));
            stepper.Reset(new FlightState(default, new Vector3d(10, 0, 3), default));
            stepper.TryStep(0.01);
            Assert.That(stepper.TryGetEvent(FlightEventKinds.Landing, out _), Is.False);
        }

        [Test]
        public void EventsInOneStep_ComeInTimeOrder()
        {
            var model = FlightModel.Vacuum(Ball.Tennis, new Vector3d(0, 0, -10));
            var events = new FlightEventSet(Vector3d.UnitZ, new Plane(default, Vector3d.UnitZ),
                new[] { new Plane(new Vector3d(15, 0, 0), Vector3d.UnitX), new Plane(new Vector3d(5, 0, 0), Vector3d.UnitX) });
            var stepper = new FlightStepper(model, RungeKutta4.Instance, events);
            stepper.Reset(new FlightState(new Vector3d(0, 0, 0.5), new Vector3d(10, 0, 10), default));
            stepper.TryStep(3.0);
            int count = stepper.Events.Length; // one step holds everything: x=5 at 0.5 s, apex 1 s, x=15 at 1.5 s, landing ~2.05 s
            Assert.That(count, Is.EqualTo(4));
            FlightEvent[] e = stepper.Events.ToArray(); // a copy: Mono 6.8 has no ReadOnlySpan indexer a compiler accepts (SpanView)
            Assert.That(e[0].Kind, Is.EqualTo(FlightEventKinds.PlaneCrossing));
            Assert.That(e[0].PlaneIndex, Is.EqualTo(1));
            Assert.That(e[0].Time, Is.EqualTo(0.5).Within(1e-12));
            Assert.That(e[1].Kind, Is.EqualTo(FlightEventKinds.Apex));
            Assert.That(e[1].Time, Is.EqualTo(1.0).Within(1e-12));
            Assert.That(e[2].PlaneIndex, Is.EqualTo(0));
            Assert.That(e[2].Time, Is.EqualTo(1.5).Within(1e-12));
            Assert.That(e[3].Kind, Is.EqualTo(FlightEventKinds.Landing));
            Assert.That(e[3].Time, Is.EqualTo(1 + Math.Sqrt(1.1)).Within(1e-12));
        }

        [Test]
        public void YUpFrame_GivesTheSameLanding()
        {
            var zModel = Shots.StepanekTennis(Gravity.ZUp);
            var yModel = Shots.StepanekTennis(Gravity.YUp);
            FlightEvent z = FlyToLanding(zModel, RungeKutta4.Instance, TennisDrive(Vector3d.UnitZ), 1.0 / 240);
            FlightEvent y = FlyToLanding(yModel, RungeKutta4.Instance, TennisDrive(Vector3d.UnitY), 1.0 / 240);
            Assert.That(y.Time, Is.EqualTo(z.Time).Within(1e-12));
            Assert.That(y.Position.Y, Is.EqualTo(z.Position.Z).Within(1e-12));
            Assert.That(y.Position.X, Is.EqualTo(z.Position.X).Within(1e-12));
        }

        /// <summary>
        /// The crossing search skips steps whose cubic cannot reach the plane (a bound from the Hermite basis). Over
        /// 30,000 seeded random steps, many of them grazing the plane, it must still find every crossing that dense
        /// sampling of the same cubic sees, and report none where the cubic stays clearly above the plane.
        /// </summary>
        [Test]
        public void CrossingSearch_FindsEveryCrossingSamplingSees_AndNoneWhereTheCubicStaysAbove()
        {
            var random = new Random(20261202);
            var ground = new Plane(Vector3d.Zero, Vector3d.UnitZ);
            const double h = 0.01;
            int found = 0, missed = 0, spurious = 0;
            for (int n = 0; n < 30_000; n++)
            {
                double f0 = random.NextDouble() + 1e-3, f1 = random.NextDouble() + 1e-3;
                double m0 = -4 * random.NextDouble() + 0.5, m1 = 4 * random.NextDouble() - 0.5; // down into the step, up out of it
                var start = new FlightState(new Vector3d(0, 0, f0), new Vector3d(1, 0, m0 / h), Vector3d.Zero, 0);
                var end = new FlightState(new Vector3d(h, 0, f1), new Vector3d(1, 0, m1 / h), Vector3d.Zero, h);
                var segment = new HermiteSegment(start, new StateDerivative(start.Velocity, Vector3d.Zero, Vector3d.Zero),
                    end, new StateDerivative(end.Velocity, Vector3d.Zero, Vector3d.Zero));
                double lowest = double.PositiveInfinity;
                for (int i = 0; i <= 1000; i++)
                {
                    double s = i / 1000.0;
                    double s2 = s * s, s3 = s2 * s;
                    double f = (2 * s3 - 3 * s2 + 1) * f0 + (s3 - 2 * s2 + s) * m0 + (3 * s2 - 2 * s3) * f1 + (s3 - s2) * m1;
                    lowest = Math.Min(lowest, f);
                }

                bool crossing = segment.TryFindCrossing(ground, CrossingDirection.AgainstNormal, out double time);
                // Sampling misses dips narrower than its spacing, so only clear cases are judged: a sample at least 1e-9
                // below the plane (the search's own margin is 1e-9 of the data, |f| + |m| <= 10 here) or every sample
                // 1e-6 above it.
                if (lowest < -1e-9 && !crossing)
                {
                    missed++;
                }
                else if (lowest > 1e-6 && crossing)
                {
                    spurious++;
                }

                if (crossing)
                {
                    found++;
                    Assert.That(Math.Abs(segment.PositionAt(time).Z), Is.LessThan(1e-9), "the crossing lies on the plane");
                }
            }

            TestContext.Out.WriteLine($"{found} crossings found, {missed} missed, {spurious} spurious");
            Assert.That(missed, Is.Zero);
            Assert.That(spurious, Is.Zero);
            Assert.That(found, Is.GreaterThan(3_000), "the random steps cross the plane often enough to test the search");
        }
        [Test]
        public void QuickClearTest_NeverHidesAnEventTheSearchFinds()
        {
            // The flight core takes a step without building its segment when SurelyNoCrossing / SurelyNoApex call it clear,
            // so they must never call a step clear where the search finds a crossing (or, for a start on the plane, a
            // crossing at the start). Random scalar cubics of both signs and slopes, scaled over 12 decades, some with an
            // end exactly on the plane, and others tangent to it within a part in 1e12; a fall is also looked for by sampling.
            var random = new Random(20261203);
            var ground = new Plane(Vector3d.Zero, Vector3d.UnitZ);
            const double h = 0.01;
            int clear = 0, crossings = 0, rising = 0, clearRising = 0;
            for (int n = 0; n < 40_000; n++)
            {
                double scale = Math.Pow(10, 12 * random.NextDouble() - 6);
                double f0 = scale * (2 * random.NextDouble() - 1), f1 = scale * (2 * random.NextDouble() - 1);
                double m0 = scale * (8 * random.NextDouble() - 4), m1 = scale * (8 * random.NextDouble() - 4);
                switch (n % 8)
                {
                    case 0: f0 = 0; break;
                    case 1: f1 = 0; break;
                    case 2: f0 = -Math.Abs(f0); f1 = Math.Abs(f1) * 1e-12; break; // rises to just above the plane at the end
                    case 3: f0 = Math.Abs(f0) * 1e-12; f1 = -Math.Abs(f1); break;  // starts just above it and falls
                }

                var start = new FlightState(new Vector3d(0, 0, f0), new Vector3d(1, 0, m0 / h), Vector3d.Zero, 0);
                var end = new FlightState(new Vector3d(h, 0, f1), new Vector3d(1, 0, m1 / h), Vector3d.Zero, h);
                var startDerivative = new StateDerivative(start.Velocity, Vector3d.Zero, Vector3d.Zero);
                var endDerivative = new StateDerivative(end.Velocity, Vector3d.Zero, Vector3d.Zero);
                var segment = new HermiteSegment(start, startDerivative, end, endDerivative);
                bool isClear = HermiteSegment.SurelyNoCrossing(ground, CrossingDirection.AgainstNormal, start, startDerivative, end, endDerivative);
                bool crossing = segment.TryFindCrossing(ground, CrossingDirection.AgainstNormal, true, out _) |
                    segment.TryFindCrossing(ground, CrossingDirection.AgainstNormal, false, out _);
                Assert.That(isClear && crossing, Is.False, $"called clear with a crossing: f0 {f0:R} m0 {m0:R} f1 {f1:R} m1 {m1:R}");
                bool sampledFall = false, above = f0 > 0;
                for (int i = 1; i <= 1000 && !sampledFall; i++)
                {
                    double s = i / 1000.0, s2 = s * s, s3 = s2 * s;
                    double f = (2 * s3 - 3 * s2 + 1) * f0 + (s3 - 2 * s2 + s) * m0 + (3 * s2 - 2 * s3) * f1 + (s3 - s2) * m1;
                    sampledFall = above && f <= 0;
                    above = f > 0;
                }

                Assert.That(isClear && sampledFall, Is.False, $"called clear where sampling sees a fall: f0 {f0:R} m0 {m0:R} f1 {f1:R} m1 {m1:R}");
                clear += isClear ? 1 : 0;
                crossings += crossing ? 1 : 0;
                if (f0 < 0 && f1 < 0)
                {
                    rising++;
                    clearRising += isClear ? 1 : 0;
                }
            }

            TestContext.Out.WriteLine($"{clear} of 40000 called clear, {crossings} crossings, {clearRising} of {rising} below the plane at both ends called clear");
            Assert.That(crossings, Is.GreaterThan(5_000), "the random cubics cross the plane often enough to test the bound");
            Assert.That(clearRising, Is.GreaterThan(rising / 3), "the upper bound decides many steps that start and end below the plane");
        }

        [Test]
        public void SurelyClear_OnFlownSteps_NeverHidesAnEventTheScanFinds()
        {
            // The same rule on real RK4 steps (random drives and lobs at 1/240 s and 1/30 s) against an event set with the
            // ground, the apex and planes placed where the steps meet them: every 0.25 m of height and every metre along x
            // (both directions), plus planes through each step's midpoint and just above its top.
            FlightModel model = Shots.StepanekTennis(Gravity.Along(Vector3d.UnitZ));
            var random = new Random(5);
            int steps = 0, clear = 0, found = 0;
            var planes = new System.Collections.Generic.List<Plane>();
            for (int z = -8; z <= 80; z++)
            {
                planes.Add(new Plane(new Vector3d(0, 0, 0.25 * z), z % 2 == 0 ? Vector3d.UnitZ : -Vector3d.UnitZ));
            }

            for (int x = 0; x <= 40; x++)
            {
                planes.Add(new Plane(new Vector3d(x, 0, 0), x % 2 == 0 ? Vector3d.UnitX : -Vector3d.UnitX));
            }

            var fixedSet = new FlightEventSet(Vector3d.UnitZ, Plane.Ground(model), planes.ToArray());
            var events = new FlightEvent[fixedSet.MaximumEventsPerStep + 3];
            for (int shot = 0; shot < 40; shot++)
            {
                double elevation = -0.2 + 1.4 * random.NextDouble(), speed = 5 + 40 * random.NextDouble();
                var velocity = new Vector3d(speed * Math.Cos(elevation), 3 * (random.NextDouble() - 0.5), speed * Math.Sin(elevation));
                double rpm = 4000 * random.NextDouble() - 1000;
                Vector3d spin = rpm >= 0 ? Spin.Topspin(velocity, Vector3d.UnitZ, Spin.FromRpm(rpm)) : Spin.Backspin(velocity, Vector3d.UnitZ, Spin.FromRpm(-rpm));
                var state = new FlightState(new Vector3d(0, 0, 1 + random.NextDouble()), velocity, spin);
                StateDerivative k1 = model.Derivative(state);
                double h = shot % 2 == 0 ? 1.0 / 240 : 1.0 / 30;
                for (int i = 0; i < 1000 && state.Position.Z > -2; i++)
                {
                    FlightState next = ((IIntegrator)RungeKutta4.Instance).Step(model, state, k1, h, out StateDerivative k2, out _);
                    var segment = new HermiteSegment(state, k1, next, k2);
                    FlightState middle = segment.StateAt(state.Time + 0.5 * h);
                    double top = Math.Max(state.Position.Z, next.Position.Z);
                    var near = new[]
                    {
                        new Plane(middle.Position, Vector3d.UnitZ), new Plane(middle.Position, middle.Velocity.NormalizedOrZero()),
                        new Plane(new Vector3d(0, 0, top + 1e-9), Vector3d.UnitZ), new Plane(new Vector3d(0, 0, top + 1e-6), -Vector3d.UnitZ),
                    };
                    foreach (FlightEventSet set in new[] { fixedSet, new FlightEventSet(Vector3d.UnitZ, new Plane(state.Position, Vector3d.UnitZ), near) })
                    {
                        bool isClear = set.SurelyClear(state, k1, next, k2);
                        int count = set.Scan(ref segment, events, false, landings: true);
                        Assert.That(isClear && count > 0, Is.False, $"a step with {count} events called clear, from {state}");
                        clear += isClear ? 1 : 0;
                        found += count;
                        steps++;
                    }

                    state = next;
                    k1 = k2;
                }
            }

            TestContext.Out.WriteLine($"{steps} step-set checks, {found} events found, {clear} called clear");
            Assert.That(found, Is.GreaterThan(2_000), "the flights meet many of the planes");
            Assert.That(clear, Is.GreaterThan(steps / 4), "the quick test decides many steps");
        }
    }
}
