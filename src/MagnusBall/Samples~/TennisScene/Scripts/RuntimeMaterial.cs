using UnityEngine;

namespace MagnusBall.Samples.TennisScene.Scripts
{
    /// <summary>
    /// Gives this object's renderer (the ball's MeshRenderer, the predicted path's LineRenderer) a material of one colour at
    /// Awake, copied from the default material of the project's render pipeline (the one a new primitive gets), so the sample
    /// looks the same in the built-in pipeline, URP and HDRP without shipping a material asset per pipeline.
    /// </summary>
    /// <remarks>
    /// In the saved scene the renderers reference Unity's built-in Default-Material, which URP and HDRP draw pink in edit
    /// mode; in Play mode this script replaces it. The material is made once per object and destroyed with it.
    /// </remarks>
    public class RuntimeMaterial : MonoBehaviour
    {
        /// <summary>The colour of the material made at Awake.</summary>
        [Tooltip("The colour of the material made at Awake from the render pipeline's default material.")]
        public Color color = Color.white;

        private Material _made;

        /// <summary>The material this script made (null before Awake, or without a renderer).</summary>
        public Material Made => _made;

        private void Awake()
        {
            Renderer target = GetComponent<Renderer>();
            if (target == null)
            {
                return;
            }

            // A primitive's renderer holds the pipeline's default material: copied, then the primitive is destroyed (before
            // anything is drawn: Unity destroys at the end of the frame's updates).
            GameObject probe = GameObject.CreatePrimitive(PrimitiveType.Cube);
            _made = new Material(probe.GetComponent<Renderer>().sharedMaterial) { color = color, name = "MagnusBall sample: " + name };
            Destroy(probe);
            target.sharedMaterial = _made;
        }

        private void OnDestroy()
        {
            if (_made != null)
            {
                Destroy(_made);
            }
        }
    }
}
