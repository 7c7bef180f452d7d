using System;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Queries
{
    /// <summary>
    /// A ball that starts exactly on a plane (signed distance 0): heading through it, it crosses at the start
    /// of the first step; leaving it, it does not; and a crossing at the very end of a step is not reported again
    /// at the start of the next.
    /// </summary>
    [TestFixture]
    public class StartOnPlaneTests
    {
        private const double Step = 1.0 / 240;

        private static readonly FlightModel Model = Shots.StepanekTennis(Gravity.ZUp);

        private static FlightState OnGround(double vx, double vz) => new FlightState(Vector3d.Zero, new Vector3d(vx, 0, vz), Vector3d.Zero);

        private static HermiteSegment FirstStep(in FlightState start)
        {
            StateDerivative d0 = Model.Derivative(start);
            FlightState end = ((IIntegrator)RungeKutta4.Instance).Step(Model, start, d0, Step);
            return new HermiteSegment(start, d0, end, Model.Derivative(end));
        }

        [TestCase(5.0, -1.0, TestName = "Segment_StartOnTheGround_MovingDown")]
        [TestCase(5.0, 0.0, TestName = "Segment_StartOnTheGround_MovingLevel_GravityTakesItDown")]
        public void Segment_StartOnThePlaneHeadingThrough_CrossesAtTheStartOfAFlightOnly(double vx, double vz)
        {
            var ground = Plane.Ground(Model);
            HermiteSegment segment = FirstStep(OnGround(vx, vz));
            Assert.That(segment.TryFindCrossing(ground, CrossingDirection.AgainstNormal, true, out double time), Is.True);
            Assert.That(time, Is.EqualTo(segment.StartTime));
            Assert.That(segment.TryFindCrossing(ground, CrossingDirection.AgainstNormal, false, out _), Is.False, "a continuing step's start was the last step's end");
            Assert.That(segment.TryFindCrossing(ground, CrossingDirection.AgainstNormal, out _), Is.False, "the three-argument form continues a flight");
        }

        [Test]
        public void Segment_StartOnThePlaneLeavingIt_DoesNotCross()
        {
            var ground = Plane.Ground(Model);
            HermiteSegment segment = FirstStep(OnGround(5, 3));
            Assert.That(segment.TryFindCrossing(ground, CrossingDirection.AgainstNormal, true, out _), Is.False);
        }

        [Test]
        public void Segment_StartOnAWatchedPlane_CrossesAlongItsNormal()
        {
            var net = new Plane(Vector3d.Zero, Vector3d.UnitX);
            HermiteSegment forward = FirstStep(new FlightState(new Vector3d(0, 0, 1), new Vector3d(20, 0, 0), Vector3d.Zero));
            Assert.That(forward.TryFindCrossing(net, CrossingDirection.AlongNormal, true, out double time), Is.True);
            Assert.That(time, Is.EqualTo(forward.StartTime));
            HermiteSegment back = FirstStep(new FlightState(new Vector3d(0, 0, 1), new Vector3d(-20, 0, 0), Vector3d.Zero));
            Assert.That(back.TryFindCrossing(net, CrossingDirection.AlongNormal, true, out _), Is.False, "moving against the normal is not a crossing along it");
        }

        [Test]
        public void Predictor_LaunchedLevelFromTheGround_LandsAtOnce()
        {
            // The reviewer's case: before, this flew on under the ground to z = -78 m at 5 s with no event.
            var predictor = new TrajectoryPredictor(Model, RungeKutta4.Instance, Step);
            FlightState start = OnGround(5, 0);
            Prediction p = predictor.Predict(start, 5, Span<Vector3d>.Empty);
            Assert.That(p.Stopped, Is.True);
            Assert.That(p.StopEvent.Kind, Is.EqualTo(FlightEventKinds.Landing));
            Assert.That(p.StopEvent.Time, Is.EqualTo(0));
            Assert.That(p.EndState.Position, Is.EqualTo(start.Position));
            Assert.That(p.Steps, Is.EqualTo(1));
        }

        [Test]
        public void Stepper_StartOnTheGround_LandsInTheFirstStepAndAfterSetState()
        {
            var stepper = new FlightStepper(Model, RungeKutta4.Instance, FlightEventSet.ForModel(Model));
            stepper.Reset(OnGround(10, -2));
            stepper.TryStep(Step);
            Assert.That(stepper.TryGetEvent(FlightEventKinds.Landing, out FlightEvent landing), Is.True);
            Assert.That(landing.Time, Is.EqualTo(0));

            // Keep flying (under the ground now), then put the ball back on the ground heading down mid-flight.
            stepper.TryStep(Step);
            Assert.That(stepper.TryGetEvent(FlightEventKinds.Landing, out _), Is.False, "under the ground: no new landing");
            var placed = new FlightState(new Vector3d(1, 0, 0), new Vector3d(10, 0, -2), Vector3d.Zero, stepper.State.Time);
            stepper.SetState(placed);
            stepper.TryStep(Step);
            Assert.That(stepper.TryGetEvent(FlightEventKinds.Landing, out landing), Is.True);
            Assert.That(landing.Time, Is.EqualTo(placed.Time));
        }

        [Test]
        public void Stepper_BallLeavingTheGround_DoesNotLandUntilItComesBack()
        {
            // As after a bounce: on the ground, moving up at 3 m/s; it lands about 2 v / g = 0.6 s later.
            var stepper = new FlightStepper(Model, RungeKutta4.Instance, FlightEventSet.ForModel(Model));
            stepper.Reset(OnGround(5, 3));
            int landings = 0;
            double landedAt = double.NaN;
            for (int i = 0; i < 240; i++)
            {
                stepper.TryStep(Step);
                if (stepper.TryGetEvent(FlightEventKinds.Landing, out FlightEvent e))
                {
                    landings++;
                    landedAt = e.Time;
                    break;
                }
            }

            Assert.That(landings, Is.EqualTo(1));
            Assert.That(landedAt, Is.GreaterThan(0.5).And.LessThan(0.62), "2 x 3 / 9.81 = 0.61 s in a vacuum; drag shortens it");
        }

        [Test]
        public void Stepper_CrossingExactlyAtAStepEnd_IsReportedOnce()
        {
            // Planes through the exact position at the end of step 150 (0.625 s, past the apex), so that step ends exactly on them (signed
            // distance 0) and the next one starts on them heading through: the crossing must not be reported twice.
            FlightState drive = EventLocationTests.TennisDrive(Vector3d.UnitZ);
            var probe = new FlightStepper(Model, RungeKutta4.Instance);
            probe.Reset(drive);
            for (int i = 0; i < 150; i++)
            {
                probe.TryStep(Step);
            }

            FlightState mark = probe.State;
            Assume.That(mark.Velocity.Z, Is.LessThan(0), "falling there, so a ground through it is crossed against its normal");
            var ground = new Plane(mark.Position, Vector3d.UnitZ);
            var wall = new Plane(mark.Position, Vector3d.UnitX);
            var stepper = new FlightStepper(Model, RungeKutta4.Instance, new FlightEventSet(Vector3d.Zero, ground, new[] { wall }));
            stepper.Reset(drive);
            int landings = 0, crossings = 0;
            for (int i = 0; i < 200; i++)
            {
                stepper.TryStep(Step);
                foreach (FlightEvent e in stepper.Events)
                {
                    Assert.That(e.Time, Is.EqualTo(mark.Time), e.ToString());
                    landings += e.Kind == FlightEventKinds.Landing ? 1 : 0;
                    crossings += e.Kind == FlightEventKinds.PlaneCrossing ? 1 : 0;
                }
            }

            Assert.That(landings, Is.EqualTo(1));
            Assert.That(crossings, Is.EqualTo(1));
        }
    }
}
