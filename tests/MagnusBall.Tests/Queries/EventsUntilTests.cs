using System;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Queries
{
    /// <summary>The one "nothing after the landing" rule (FlightEventSet.CountUntil, FlightStepper.EventsUntil) that the predictor, the aim solver and the CLI share.</summary>
    [TestFixture]
    public class EventsUntilTests
    {
        private static FlightEvent At(FlightEventKinds kind, double time, int plane = -1) =>
            new FlightEvent(kind, plane, new FlightState(new Vector3d(time, 0, 0), Vector3d.UnitX, Vector3d.Zero, time));

        [Test]
        public void CountUntil_KeepsTheEventsBeforeTheStopAndAtItsInstant()
        {
            FlightEvent[] events =
            {
                At(FlightEventKinds.Apex, 0.1), At(FlightEventKinds.PlaneCrossing, 0.2, 0), At(FlightEventKinds.Landing, 0.3),
                At(FlightEventKinds.PlaneCrossing, 0.3, 1), At(FlightEventKinds.PlaneCrossing, 0.4, 2),
            };

            Assert.That(FlightEventSet.CountUntil(events.AsSpan(), FlightEventKinds.Landing, out int stop), Is.EqualTo(4), "a crossing at the landing instant counts, the later one not");
            Assert.That(stop, Is.EqualTo(2));
            Assert.That(FlightEventSet.CountUntil(events.AsSpan(), FlightEventKinds.PlaneCrossing, out stop), Is.EqualTo(2));
            Assert.That(stop, Is.EqualTo(1));
            Assert.That(FlightEventSet.CountUntil(events.AsSpan(), FlightEventKinds.None, out stop), Is.EqualTo(5));
            Assert.That(stop, Is.EqualTo(-1));
            Assert.That(FlightEventSet.CountUntil(events.AsSpan(0, 2), FlightEventKinds.Landing, out stop), Is.EqualTo(2));
            Assert.That(stop, Is.EqualTo(-1));
            Assert.That(FlightEventSet.CountUntil(Span<FlightEvent>.Empty, FlightEventKinds.All, out stop), Is.EqualTo(0));
            Assert.That(stop, Is.EqualTo(-1));
        }

        [Test]
        public void TheCore_StopsAtTheLanding_AndDropsWhatComesAfterIt()
        {
            // A long step (0.5 s) over the end of a tennis drive: it lands at about 0.83 s (x = 19.5 m) inside the step from 0.5 s to
            // 1.0 s, and a wall at 21 m, crossed only after the landing on the interpolant, must not count when the flight stops there.
            FlightModel model = Shots.StepanekTennis(Gravity.ZUp);
            var wall = new Plane(new Vector3d(21, 0, 0), Vector3d.UnitX);
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(29, 0, 4), new Vector3d(0, 100, 0));
            var through = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model, wall));
            through.Reset(start);
            through.TryStep(0.5);
            through.TryStep(0.5);
            Assert.That(through.TryGetEvent(FlightEventKinds.Landing, out FlightEvent landing), Is.True);
            Assume.That(through.TryGetEvent(FlightEventKinds.PlaneCrossing, out FlightEvent late) && late.Time > landing.Time, Is.True, "the wall is crossed after the landing on this step's cubic");
            Assert.That(through.IsStopped, Is.False, "with no stop kinds the flight goes on past the landing");

            var stopping = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model, wall));
            stopping.Reset(start);
            Assert.That(stopping.TryStep(0.5, FlightEventKinds.Landing), Is.EqualTo(StepOutcome.Taken));
            Assert.That(stopping.TryStep(0.5, FlightEventKinds.Landing), Is.EqualTo(StepOutcome.Stopped));
            Assert.That(stopping.IsStopped, Is.True);
            Assert.That(stopping.StopEvent.Kind, Is.EqualTo(FlightEventKinds.Landing));
            Assert.That(stopping.StopEvent.Time, Is.EqualTo(landing.Time));
            Assert.That(stopping.State, Is.EqualTo(landing.State), "the flight ends on the landing state");
            Assert.That(stopping.Events.Length, Is.EqualTo(through.Events.Length - 1), "everything but the later wall crossing");
            foreach (FlightEvent e in stopping.Events)
            {
                Assert.That(e.Time, Is.LessThanOrEqualTo(landing.Time), e.ToString());
            }

            Assert.That(stopping.TryStep(0.5, FlightEventKinds.Landing), Is.EqualTo(StepOutcome.AlreadyStopped));
            Assert.That(stopping.State, Is.EqualTo(landing.State));
        }
    }
}
