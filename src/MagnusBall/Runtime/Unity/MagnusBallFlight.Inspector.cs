// MagnusBallFlight, the inspector side: edits applied during Play (OnValidate) and the gizmos of the selected ball. The flight itself is in MagnusBallFlight.cs.
#nullable enable
using System;
using MagnusBall.Queries;
using UnityEngine;

namespace MagnusBall.Components
{
    public partial class MagnusBallFlight
    {
        /// <summary>
        /// Unity calls this after an inspector edit (also during Play) and when the component is loaded: the inspector's
        /// fields are checked and applied as <see cref="ApplySettings"/> applies them, and a ball in flight flies on under them
        /// from its current state. A refused value is reported once with <c>Debug.LogError</c>, naming the field; the previous
        /// settings stay. Nothing happens while a configuration given in code (<see cref="Configure"/>) is in use.
        /// </summary>
        private void OnValidate()
        {
            if (_configuredInCode)
            {
                return;
            }

            try
            {
                ApplySettings();
                _reported = null;
                if (_flying && _driver != null && !_driver.IsFinished)
                {
                    StartFlight(Build(_driver.State, _model!, _integrator!, _fixedStep, _eventSet!, _bounce, _maxFrameDelta, _shapes), announce: false);
                }
            }
            catch (ArgumentException e)
            {
                UnityFrame.ReportRefusal(ref _reported, this, e);
            }
        }

        /// <summary>
        /// Unity calls this when the object is selected in the Scene view: the current arc (from the launch or the latest bounce to
        /// the next touch of the ground; nothing before the first launch) in yellow, the ground plane around the ball in green, the
        /// watched plane in cyan. Nothing is drawn while the inspector's settings are refused.
        /// </summary>
        private void OnDrawGizmosSelected()
        {
            try
            {
                EnsureConfigured();
            }
            catch (ArgumentException)
            {
                return; // OnValidate reports it
            }

            Vector3d centre = UnityFrame.ToLibrary(transform.position);
            const double halfSize = 2; // m: the patch of each plane drawn around the ball
            if (_eventSet!.Ground is Plane ground)
            {
                Gizmos.color = Color.green;
                DrawPlanePatch(new Plane(ground.Project(centre) - ground.Normal * _model!.Ball.Radius, ground.Normal), centre, halfSize);
            }

            Gizmos.color = Color.cyan;
            foreach (Plane watched in _eventSet.Planes)
            {
                DrawPlanePatch(watched, centre, halfSize);
            }

            if (_driver == null)
            {
                return;
            }

            _gizmoPath ??= new Vector3d[1024];
            var predictor = new TrajectoryPredictor(_model!, _integrator!, _fixedStep, _eventSet, _shapes);
            int count = predictor.Predict(_segmentStart, 10, _gizmoPath).SampleCount;
            Gizmos.color = Color.yellow;
            for (int i = 1; i < count; i++)
            {
                Gizmos.DrawLine(UnityFrame.ToUnity(_gizmoPath[i - 1]), UnityFrame.ToUnity(_gizmoPath[i]));
            }
        }

        // A square of the plane, 2 halfSize across, centred on the foot of `near` on it, with its two diagonals.
        private static void DrawPlanePatch(in Plane plane, Vector3d near, double halfSize)
        {
            Vector3d n = plane.Normal.NormalizedOrZero();
            Vector3d any = Math.Abs(n.Y) < 0.9 ? UnityFrame.Up : new Vector3d(1, 0, 0);
            Vector3d u = Vector3d.Cross(n, any).NormalizedOrZero() * halfSize;
            Vector3d v = Vector3d.Cross(n, u).NormalizedOrZero() * halfSize;
            Vector3d c = plane.Project(near);
            Vector3 a = UnityFrame.ToUnity(c + u + v), b = UnityFrame.ToUnity(c + u - v), d = UnityFrame.ToUnity(c - u - v), e = UnityFrame.ToUnity(c - u + v);
            Gizmos.DrawLine(a, b);
            Gizmos.DrawLine(b, d);
            Gizmos.DrawLine(d, e);
            Gizmos.DrawLine(e, a);
            Gizmos.DrawLine(a, d);
            Gizmos.DrawLine(b, e);
        }

        /// <summary>How far below the ground's touchdown plane a launch may start and be lifted onto it, m (0.1 mm: a float position meant to be on it).</summary>
        public const double GroundTolerance = 1e-4;
    }
}
