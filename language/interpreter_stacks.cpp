// The transforms a block collects (the value stack is language/value_stack.hpp).
// Part of the Interpreter (language/interpreter_state.hpp).
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>

#include "language/checked_integer.hpp"
#include "language/interpreter.hpp"
#include "language/interpreter_state.hpp"
#include "runtime/objects/parameter_check.hpp"

namespace hexant::language {

// ------------------------------------------------------------------ stacks

void Interpreter::apply_transform(runtime::TransformStep step, const p::position& where) {
    if (blocks.empty()) fail(where, "a transformation does not belong here");
    Block& b = blocks.top();
    if (auto* object = std::get_if<runtime::ObjectRecord>(&b)) {
        // As in POV-Ray, an object's texture moves with it.
        if (object->texture) object->texture->transform_by(step);
        if (object->interior) object->interior->transform_by(step);
        if (object->interior_texture) {
            auto inside = std::make_shared<runtime::Texture>(*object->interior_texture);
            inside->transform_by(step);
            object->interior_texture = std::move(inside);
        }
        object->transform.append(std::move(step));
    } else if (auto* light = std::get_if<runtime::LightRecord>(&b)) {
        light->transform.append(std::move(step));
    } else if (auto* camera = std::get_if<runtime::CameraRecord>(&b)) {
        runtime::CameraItem item;
        item.kind = runtime::CameraItem::Kind::Transform;
        item.step = std::move(step);
        camera->items.push_back(std::move(item));
    } else if (auto* texture = std::get_if<runtime::Texture>(&b)) {
        texture->transform_by(step);
    } else if (auto* pigment = std::get_if<runtime::Pigment>(&b)) {
        // (A declared uv-mapped pigment takes no transform from outside
        // its own block, as in POV-Ray: runtime/texture/material.hpp, UvMapping.)
        if (pigment->uv_mapping != runtime::UvMapping::Closed)
            pigment->transform.append(std::move(step));
    } else if (auto* normal = std::get_if<runtime::Normal>(&b)) {
        if (normal->uv_mapping != runtime::UvMapping::Closed)
            normal->transform.append(std::move(step));
    } else if (auto* media = std::get_if<runtime::Media>(&b)) {
        media->transform_by(step);
    } else if (auto* fog = std::get_if<runtime::Fog>(&b)) {
        // (POV-Ray turns a fog's up vector; a translation does not move it.)
        if (step.kind == runtime::TransformKind::Translate) return;
        fog->up_transform.append(std::move(step));
    } else if (auto* sky = std::get_if<runtime::SkySphere>(&b)) {
        sky->transform.append(std::move(step));
    } else if (auto* transform = std::get_if<runtime::Transform>(&b)) {
        transform->append(std::move(step));
    } else if (auto* material = std::get_if<MaterialBuilder>(&b)) {
        if (material->texture) material->texture->transform_by(step);
        if (material->interior) material->interior->transform_by(step);
    } else {
        fail(where, "a transformation does not belong here");
    }
}

void Interpreter::apply_deformation(runtime::TransformStep step, const p::position& where) {
    if (blocks.empty() || !std::holds_alternative<runtime::ObjectRecord>(blocks.top()))
        fail(where, "a deformation belongs in an object");
    apply_transform(std::move(step), where);
}

}  // namespace hexant::language
