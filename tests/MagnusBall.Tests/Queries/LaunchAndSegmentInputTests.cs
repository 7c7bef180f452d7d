using System;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Queries
{
    /// <summary>Bad input to the launch description, the Hermite segment and the net-clearing solve, and the sidespin of a launch along the frame's side.</summary>
    [TestFixture]
    public class LaunchAndSegmentInputTests
    {
        private static readonly LaunchFrame Frame = new LaunchFrame(Vector3d.UnitZ, Vector3d.UnitX);

        [TestCase(double.NaN, 0.0, "elevationRadians")]
        [TestCase(0.0, double.NaN, "azimuthRadians")]
        [TestCase(double.PositiveInfinity, 0.0, "elevationRadians")]
        [TestCase(0.0, double.NegativeInfinity, "azimuthRadians")]
        public void Direction_RejectsNonFiniteAngles(double elevation, double azimuth, string name)
        {
            var ex = Assert.Throws<ArgumentOutOfRangeException>(() => Frame.Direction(elevation, azimuth));
            Assert.That(ex!.ParamName, Is.EqualTo(name));
            Assert.That(ex.Message, Does.Contain("finite"));
        }

        [Test]
        public void AngularVelocity_RejectsAZeroOrNonFiniteDirectionAndTheDefaultFrame()
        {
            var spin = new LaunchSpin(10, 5, 1);
            var ex = Assert.Throws<ArgumentException>(() => spin.AngularVelocity(Vector3d.Zero, Frame));
            Assert.That(ex!.ParamName, Is.EqualTo("direction"));
            Assert.That(ex.Message, Does.Contain("non-zero"));
            ex = Assert.Throws<ArgumentException>(() => spin.AngularVelocity(new Vector3d(double.NaN, 0, 0), Frame));
            Assert.That(ex!.ParamName, Is.EqualTo("direction"));
            ex = Assert.Throws<ArgumentException>(() => spin.AngularVelocity(Vector3d.UnitX, default));
            Assert.That(ex!.ParamName, Is.EqualTo("frame"));
        }

        [TestCase(0.0, TestName = "Sidespin_LaunchAlongSide_Level_IsTheLimitFromForwardAims")]
        [TestCase(30.0, TestName = "Sidespin_LaunchAlongSide_Elevated_IsTheLimitFromForwardAims")]
        public void Sidespin_LaunchAlongSide_IsTheLimitFromForwardAims(double elevationDegrees)
        {
            var spin = new LaunchSpin(0, 10);
            double e = elevationDegrees * Math.PI / 180;
            foreach (double sign in new[] { 1.0, -1.0 })
            {
                // Along +-Side exactly (built from the frame's vectors, not from cos(pi/2)).
                Vector3d along = Frame.Side * (sign * Math.Cos(e)) + Frame.Up * Math.Sin(e);
                Vector3d w = spin.AngularVelocity(along, Frame);
                Assert.That(w.Length, Is.EqualTo(10).Within(1e-12), "sidespin does not vanish");
                Assert.That(Vector3d.Dot(w, along), Is.EqualTo(0).Within(1e-12), "still across the launch direction");

                // 1e-7 rad short of +-90 degrees azimuth: the direction moves by 1e-7, so w by about 1e-6 rad/s.
                Vector3d near = spin.AngularVelocity(Frame.Direction(e, sign * (0.5 * Math.PI - 1e-7)), Frame);
                Assert.That(Vector3d.Distance(w, near), Is.LessThan(1e-5), $"sign {sign}: {w} vs {near}");
            }
        }

        // One RK4 step of 0.01 s of a tennis drive, with its end derivatives.
        private static void OneStep(out FlightModel model, out FlightState start, out StateDerivative d0, out FlightState end, out StateDerivative d1)
        {
            model = Shots.StepanekTennis(Gravity.ZUp);
            start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(20, 0, 3), Vector3d.Zero);
            d0 = model.Derivative(start);
            end = ((IIntegrator)RungeKutta4.Instance).Step(model, start, d0, 0.01);
            d1 = model.Derivative(end);
        }

        [Test]
        public void HermiteSegment_RejectsNonFiniteStatesAndDerivatives()
        {
            OneStep(out _, out FlightState start, out StateDerivative d0, out FlightState end, out StateDerivative d1);
            var nanState = new FlightState(new Vector3d(double.NaN, 0, 0), end.Velocity, end.AngularVelocity, end.Time);
            var infDerivative = new StateDerivative(d1.Velocity, new Vector3d(0, 0, double.NegativeInfinity), d1.AngularAcceleration);

            Assert.That(Assert.Throws<ArgumentException>(() => new HermiteSegment(start, d0, nanState, d1))!.ParamName, Is.EqualTo("end"));
            Assert.That(Assert.Throws<ArgumentException>(() => new HermiteSegment(nanState, d0, end, d1))!.ParamName, Is.EqualTo("start"));
            Assert.That(Assert.Throws<ArgumentException>(() => new HermiteSegment(start, infDerivative, end, d1))!.ParamName, Is.EqualTo("startDerivative"));
            var ex = Assert.Throws<ArgumentException>(() => new HermiteSegment(start, d0, end, infDerivative));
            Assert.That(ex!.ParamName, Is.EqualTo("endDerivative"));
            Assert.That(ex.Message, Does.Contain("finite"));
            Assert.DoesNotThrow(() => new HermiteSegment(start, d0, end, d1));
        }

        [Test]
        public void DenseOutputQueries_RefuseANaNTime_AnUndefinedDirection_AndABadStep()
        {
            // Before (a review's probes): StateAt(NaN) gave an all-NaN state, TryFindCrossing took (CrossingDirection)7, and
            // StepToward(0, 1, 0) returned a step of 0 (or -1, or the step for a NaN end time).
            OneStep(out FlightModel model, out FlightState start, out StateDerivative d0, out FlightState end, out StateDerivative d1);
            var segment = new HermiteSegment(start, d0, end, d1);
            void Named(string name, TestDelegate action) =>
                Assert.That(((ArgumentException)Assert.Throws(Is.InstanceOf<ArgumentException>(), action)!).ParamName, Is.EqualTo(name));

            Named("time", () => segment.StateAt(double.NaN));
            Named("time", () => segment.StateAt(double.PositiveInfinity));
            Named("direction", () => segment.TryFindCrossing(Plane.Ground(model), (CrossingDirection)7, out _));
            Named("direction", () => segment.TryFindCrossing(Plane.Ground(model), (CrossingDirection)(-1), false, out _));
            Assert.That(segment.StateAt(0.005).Time, Is.EqualTo(0.005));

            var stepper = new MagnusBall.Flight.FlightStepper(model, RungeKutta4.Instance, MagnusBall.Flight.FlightEventSet.ForModel(model));
            stepper.Reset(start);
            stepper.TryStep(0.01);
            Named("time", () => stepper.StateAt(double.NaN));
            Assert.That(stepper.StateAt(0.005).Time, Is.EqualTo(0.005));

            Named("step", () => MagnusBall.Flight.FlightStepper.StepToward(0, 1, 0, out _));
            Named("step", () => MagnusBall.Flight.FlightStepper.StepToward(0, 1, -1, out _));
            Named("endTime", () => MagnusBall.Flight.FlightStepper.StepToward(0, double.NaN, 0.1, out _));
            Named("now", () => MagnusBall.Flight.FlightStepper.StepToward(double.NegativeInfinity, 1, 0.1, out _));
            Assert.That(MagnusBall.Flight.FlightStepper.StepToward(0, 1, 0.3, out bool last), Is.EqualTo(0.3));
            Assert.That(last, Is.False);
            Assert.That(MagnusBall.Flight.FlightStepper.StepToward(0.9, 1, 0.3, out last), Is.EqualTo(1 - 0.9));
            Assert.That(last, Is.True);
        }

        [Test]
        public void MinimumElevationToClear_FromTheWrongSideOfThePlane_NamesThePosition()
        {
            FlightModel model = Shots.StepanekTennis(Gravity.ZUp);
            var solver = new AimSolver(model, RungeKutta4.Instance, 1.0 / 120, Plane.Ground(model));
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            foreach (double x in new[] { 20.0, 11.885 })
            {
                var ex = Assert.Throws<ArgumentException>(() => solver.MinimumElevationToClear(new Vector3d(x, 0, 1), 30, 0, LaunchSpin.None, net, 0.914));
                Assert.That(ex!.ParamName, Is.EqualTo("position"));
                Assert.That(ex.Message, Does.Contain("negative side"));
            }

            // The flipped net is cleared from the far side.
            AimSolution back = solver.MinimumElevationToClear(new Vector3d(20, 0, 1), 30, 0, LaunchSpin.None, net.Flipped(), 0.914);
            Assert.That(back.IsSolved, Is.True);
        }
    }
}
